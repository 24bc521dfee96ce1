// Tape::evalInterval4: f over four boxes per pass. This file holds the choice of path and the
// scalar path, the reference: slots as structures of arrays (four lo, four hi, four flags per
// instruction), each lane run through applyIntervalOp, the kernel evalInterval runs, so every
// lane is evalInterval's result by construction. The AVX2 path is in
// csg/tape/tape_eval_interval4_avx2.cpp.
#include "csg/tape/tape_eval_interval4.h"
#include "csg/interval/interval_ops.h"
#include "csg/tape/noise.h"
#include "csg/tape/scalar_field.h"
#include "csg/tape/tape.h"

#include <cstdlib>
#include <cstring>

namespace kerf {
namespace {

/// One instruction's result over the four boxes.
struct Slot4 {
    double lo[4], hi[4];
    bool nan[4];

    Interval lane(int k) const { return {lo[k], hi[k], nan[k]}; }
    void set(int k, const Interval& v) { lo[k] = v.lo, hi[k] = v.hi, nan[k] = v.maybeNan; }
};

void evalScalar(const Tape& tape, const Interval x[4], const Interval y[4], const Interval z[4],
                Interval out[4]) {
    const std::vector<TapeInstr>& instrs = tape.instrs();
    thread_local std::vector<Slot4> slots;
    const size_t n = instrs.size();
    if (slots.size() < n) slots.resize(n);
    Slot4* s = slots.data();
    for (size_t i = 0; i < n; ++i) {
        const TapeInstr& in = instrs[i];
        Slot4& r = s[i];
        switch (in.op) {
            case Op::Const:
                for (int k = 0; k < 4; ++k) r.set(k, Interval(in.value));
                break;
            case Op::VarX:
                for (int k = 0; k < 4; ++k) r.set(k, x[k]);
                break;
            case Op::VarY:
                for (int k = 0; k < 4; ++k) r.set(k, y[k]);
                break;
            case Op::VarZ:
                for (int k = 0; k < 4; ++k) r.set(k, z[k]);
                break;
            case Op::Noise:
                for (int k = 0; k < 4; ++k)
                    r.set(k, gradientNoiseRange(s[in.a].lane(k), s[in.b].lane(k), s[in.c].lane(k),
                                                noiseSeed(in)));
                break;
            case Op::Field:
                for (int k = 0; k < 4; ++k)
                    r.set(k,
                          tape.field(in).range(s[in.a].lane(k), s[in.b].lane(k), s[in.c].lane(k)));
                break;
            default:
                for (int k = 0; k < 4; ++k)
                    r.set(k, applyIntervalOp(in.op, s[in.a].lane(k),
                                             in.b >= 0 ? s[in.b].lane(k) : Interval(), in.value));
        }
    }
    for (int k = 0; k < 4; ++k) out[k] = s[n - 1].lane(k);
}

/// Auto's choice, made once: AVX2 when the CPU has it, unless KERF_SIMD=scalar.
bool autoUsesAvx2() {
    static const bool use = [] {
        const char* v = std::getenv("KERF_SIMD");
        return Tape::hasAvx2() && !(v && std::strcmp(v, "scalar") == 0);
    }();
    return use;
}

}  // namespace

bool Tape::hasAvx2() {
    static const bool has = __builtin_cpu_supports("avx2");
    return has;
}

void Tape::evalInterval4(const Interval x[4], const Interval y[4], const Interval z[4],
                         Interval out[4], Lanes4 lanes) const {
    const bool avx2 = lanes == Lanes4::Avx2 ? hasAvx2() : lanes == Lanes4::Auto && autoUsesAvx2();
    if (avx2 && interval4::evalAvx2(mInstrs, x, y, z, out)) return;
    evalScalar(*this, x, y, z, out);
}

}  // namespace kerf
