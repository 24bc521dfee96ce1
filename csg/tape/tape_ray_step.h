/// @file csg/tape/tape_ray_step.h
/// @brief The arithmetic of interval evaluation along a ray (value and d/dt per slot), shared
/// by Tape::evalIntervalAlongRay (csg/tape/tape_eval_ray.cpp) and TapeRayProgram
/// (csg/tape/tape_ray_program.cpp). Internal to csg/.
#pragma once

#include "csg/interval/interval_ops.h"
#include "csg/interval/interval_trig.h"
#include "csg/interval/scalar_ops.h"
#include "csg/tape/derivative_rules.h"
#include "csg/tape/tape.h"

namespace kerf::ray_step {

struct IntervalDual {
    Interval v;
    Interval d;
};

/// A slot of the evaluation: value and derivative, plus sin and cos of the value once an
/// instruction has asked for them.
struct RaySlot : IntervalDual {
    bool zeroSlope;  ///< d is exactly [0, 0] (no NaN flag): terms with it vanish exactly
    bool hasTrig;
    Interval sinV, cosV;
};

inline bool isExactZero(const Interval& a) { return a.lo == 0.0 && a.hi == 0.0 && !a.maybeNan; }

/// k·a.d; when a.d is exactly 0 the product is exactly 0 (the NaN flag of k carries over).
[[gnu::always_inline]] inline Interval scaledSlope(const Interval& k, const RaySlot& a) {
    return a.zeroSlope ? Interval(0.0, 0.0, k.maybeNan) : interval_kernel::mul(k, a.d);
}

/// x + y, exact when either is exactly 0.
[[gnu::always_inline]] inline Interval sum(const Interval& x, const Interval& y) {
    if (isExactZero(y)) return x;
    if (isExactZero(x)) return y;
    return interval_kernel::add(x, y);
}

/// The point o + t·d of one axis along the ray, and its slope d.
[[gnu::always_inline]] inline void alongAxis(double origin, double dir, const Interval& t,
                                             RaySlot& r) {
    using namespace interval_kernel;
    r.v = dir == 0.0 ? Interval(origin) : add(Interval(origin), mul(t, Interval(dir)));
    r.d = Interval(dir);
}

/// d op(a, b)/dt over the region: the shared rule (csg/tape/derivative_rules.h).
inline Interval slope(Op op, const IntervalDual& a, const IntervalDual& b, double value,
                      const Interval& r) {
    return derivative_rules::derivative(op, a.v, a.d, b.v, b.d, value, r);
}

/// The second operand of a unary instruction.
inline const IntervalDual kNoOperand{Interval(), Interval()};

/// One instruction that is not an input (x, y, z, constant) of an along-ray evaluation: r from
/// the earlier slots s[ia], s[ib] (ib < 0: unary). Shared by Tape::evalIntervalAlongRay and
/// TapeRayProgram::eval, so the two give the same enclosure for the same operands.
// Always inlined: it is the body of the root finder's innermost loop (measured: 1.9 % more
// instructions on the gyroid when GCC kept it out of line).
[[gnu::always_inline]] inline void evalStep(Op op, int32_t ia, int32_t ib, double value, RaySlot* s,
                                            RaySlot& r) {
    switch (op) {
        case Op::Sin:
        case Op::Cos: {
            RaySlot& a = s[ia];
            if (!a.hasTrig) {
                if (!interval_trig::trySinCosFast(a.v, a.sinV, a.cosV)) sinCos(a.v, a.sinV, a.cosV);
                a.hasTrig = true;
            }
            if (op == Op::Sin) {
                r.v = a.sinV;
                r.d = scaledSlope(a.cosV, a);
            } else {
                r.v = a.cosV;
                r.d = -scaledSlope(a.sinV, a);
            }
            break;
        }
        case Op::Add:
            r.v = interval_kernel::add(s[ia].v, s[ib].v);
            r.d = sum(s[ia].d, s[ib].d);
            break;
        case Op::Sub:
            r.v = interval_kernel::sub(s[ia].v, s[ib].v);
            r.d = sum(s[ia].d, -s[ib].d);
            break;
        case Op::Mul: {
            const RaySlot &a = s[ia], &b = s[ib];
            r.v = interval_kernel::mul(a.v, b.v);
            r.d = sum(scaledSlope(b.v, a), scaledSlope(a.v, b));
            break;
        }
        default: {
            const IntervalDual& a = s[ia];
            const IntervalDual& b = ib >= 0 ? static_cast<const IntervalDual&>(s[ib]) : kNoOperand;
            r.v = applyIntervalOp(op, a.v, b.v, value);
            r.d = slope(op, a, b, value, r.v);
        }
    }
}

}  // namespace kerf::ray_step
