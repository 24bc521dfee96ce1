// Interval evaluation of a tape over a box, with per-thread scratch slots.
#include "csg/interval/interval_ops.h"
#include "csg/tape/noise.h"
#include "csg/tape/scalar_field.h"
#include "csg/tape/tape.h"

namespace kerf {

Interval Tape::evalInterval(const Interval& x, const Interval& y, const Interval& z) const {
    thread_local std::vector<Interval> slots;
    slots.resize(mInstrs.size());
    Interval* s = slots.data();
    for (size_t i = 0; i < mInstrs.size(); ++i) {
        const TapeInstr& in = mInstrs[i];
        switch (in.op) {
            case Op::Const: s[i] = Interval(in.value); break;
            case Op::VarX: s[i] = x; break;
            case Op::VarY: s[i] = y; break;
            case Op::VarZ: s[i] = z; break;
            case Op::Noise:
                s[i] = gradientNoiseRange(s[in.a], s[in.b], s[in.c], noiseSeed(in));
                break;
            case Op::Field: s[i] = field(in).range(s[in.a], s[in.b], s[in.c]); break;
            default:
                s[i] = applyIntervalOp(in.op, s[in.a], in.b >= 0 ? s[in.b] : Interval(), in.value);
        }
    }
    return s[mInstrs.size() - 1];
}

}  // namespace kerf
