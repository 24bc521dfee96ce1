// Point evaluation of a tape on doubles, with per-thread scratch slots.
#include "csg/interval/interval_trig.h"
#include "csg/interval/scalar_ops.h"
#include "csg/tape/noise.h"
#include "csg/tape/scalar_field.h"
#include "csg/tape/tape.h"

namespace kerf {

double Tape::eval(const Vec3& p) const {
    // Reused per thread: no allocation once a thread has seen its largest tape.
    thread_local std::vector<double> slots;
    if (slots.size() < mInstrs.size()) slots.resize(mInstrs.size());
    double* s = slots.data();
    for (size_t i = 0; i < mInstrs.size(); ++i) {
        const TapeInstr& in = mInstrs[i];
        switch (in.op) {
            case Op::Const: s[i] = in.value; break;
            case Op::VarX: s[i] = p.x; break;
            case Op::VarY: s[i] = p.y; break;
            case Op::VarZ: s[i] = p.z; break;
            // The commonest ops inline (root isolation asks for millions of points); the
            // same arithmetic as applyScalarOp, so the same bits.
            case Op::Add: s[i] = s[in.a] + s[in.b]; break;
            case Op::Sub: s[i] = s[in.a] - s[in.b]; break;
            case Op::Mul: s[i] = s[in.a] * s[in.b]; break;
            case Op::Square: s[i] = s[in.a] * s[in.a]; break;
            case Op::Neg: s[i] = -s[in.a]; break;
            case Op::Sin:
            case Op::Cos: {  // no libm call in range; the same values as evalGradient
                double sv, cv;
                interval_trig::pointSinCos(s[in.a], sv, cv);
                s[i] = in.op == Op::Sin ? sv : cv;
                break;
            }
            case Op::Noise:
                s[i] = gradientNoise(Vec3(s[in.a], s[in.b], s[in.c]), noiseSeed(in));
                break;
            case Op::Field: s[i] = field(in).value(Vec3(s[in.a], s[in.b], s[in.c])); break;
            default: s[i] = applyScalarOp(in.op, s[in.a], in.b >= 0 ? s[in.b] : 0.0, in.value);
        }
    }
    return s[mInstrs.size() - 1];
}

}  // namespace kerf

namespace kerf {

long double Tape::evalExtended(const glm::tvec3<long double>& p) const {
    std::vector<long double> s(mInstrs.size());  // reference path: clarity over speed
    for (size_t i = 0; i < mInstrs.size(); ++i) {
        const TapeInstr& in = mInstrs[i];
        switch (in.op) {
            case Op::Const: s[i] = in.value; break;
            case Op::VarX: s[i] = p.x; break;
            case Op::VarY: s[i] = p.y; break;
            case Op::VarZ: s[i] = p.z; break;
            case Op::Noise:
                s[i] = gradientNoise(glm::tvec3<long double>(s[in.a], s[in.b], s[in.c]),
                                     noiseSeed(in));
                break;
            case Op::Field:
                s[i] = field(in).valueExtended(glm::tvec3<long double>(s[in.a], s[in.b], s[in.c]));
                break;
            default:
                s[i] = applyScalarOp<long double>(in.op, s[in.a], in.b >= 0 ? s[in.b] : 0.0L,
                                                  in.value);
        }
    }
    return s.back();
}

}  // namespace kerf
