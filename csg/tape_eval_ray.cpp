// Interval evaluation along a ray with the derivative in t: forward-mode differentiation on
// intervals. Each slot holds an enclosure of the value and one of d/dt over the t-interval.
// Where an operation is not differentiable or not continuous on the enclosure (abs or min/max
// at a kink, floor/ceil at a jump), the derivative enclosure is widened to hold every one-sided
// slope (kinks) or made entire (jumps), so "0 ∉ df/dt" still proves strict monotonicity.
//
// Root isolation calls this millions of times per image, so the common operations have a fast
// path: sin and cos of one operand share a single sinCos (each needs the other for its slope),
// and a derivative that is exactly 0 (constants, axes the ray does not move along) is not
// multiplied or added, which is exact.
#include "csg/interval_ops.h"
#include "csg/tape.h"

namespace kerf {
namespace {

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

bool isExactZero(const Interval& a) { return a.lo == 0.0 && a.hi == 0.0 && !a.maybeNan; }

/// k·a.d; when a.d is exactly 0 the product is exactly 0 (the NaN flag of k carries over).
Interval scaledSlope(const Interval& k, const RaySlot& a) {
    return a.zeroSlope ? Interval(0.0, 0.0, k.maybeNan) : interval_kernel::mul(k, a.d);
}

/// x + y, exact when either is exactly 0.
Interval sum(const Interval& x, const Interval& y) {
    if (isExactZero(y)) return x;
    if (isExactZero(x)) return y;
    return interval_kernel::add(x, y);
}

/// The point o + t·d of one axis along the ray, and its slope d.
void alongAxis(double origin, double dir, const Interval& t, RaySlot& r) {
    using namespace interval_kernel;
    r.v = dir == 0.0 ? Interval(origin) : add(Interval(origin), mul(t, Interval(dir)));
    r.d = Interval(dir);
}

Interval slope(Op op, const IntervalDual& a, const IntervalDual& b, double value,
               const Interval& r) {
    switch (op) {
        case Op::Neg:
            return -a.d;
        case Op::Square:
            return Interval(2.0) * a.v * a.d;
        case Op::Sqrt:
            return a.d / (Interval(2.0) * r);
        case Op::Abs:
            if (a.v.lo >= 0.0) return a.d;
            if (a.v.hi <= 0.0) return -a.d;
            return hull(a.d, -a.d);
        case Op::Sin:
            return cos(a.v) * a.d;
        case Op::Cos:
            return -(sin(a.v) * a.d);
        case Op::Tan:
            return (Interval(1.0) + sqr(r)) * a.d;
        case Op::Asin:
            return a.d / sqrt(Interval(1.0) - sqr(a.v));
        case Op::Acos:
            return -(a.d / sqrt(Interval(1.0) - sqr(a.v)));
        case Op::Atan:
            return a.d / (Interval(1.0) + sqr(a.v));
        case Op::Exp:
            return r * a.d;
        case Op::Log:
            return a.d / a.v;
        case Op::Floor:
        case Op::Ceil:
            // Constant where the enclosure holds no integer step; a jump otherwise.
            return r.lo == r.hi ? Interval(0.0, 0.0, a.d.maybeNan) : Interval::entire();
        case Op::Add:
            return a.d + b.d;
        case Op::Sub:
            return a.d - b.d;
        case Op::Mul:
            return a.d * b.v + a.v * b.d;
        case Op::Div:
            return (a.d - r * b.d) / b.v;
        case Op::Pow: {
            Interval d = b.v * pow(a.v, b.v - Interval(1.0)) * a.d;
            if (!(b.d.lo == 0.0 && b.d.hi == 0.0)) d = d + r * log(a.v) * b.d;
            return d;
        }
        case Op::Atan2:
            return (b.v * a.d - a.v * b.d) / (sqr(a.v) + sqr(b.v));
        case Op::Min:
            if (a.v.hi <= b.v.lo) return a.d;
            if (b.v.hi <= a.v.lo) return b.d;
            return hull(a.d, b.d);
        case Op::Max:
            if (a.v.lo >= b.v.hi) return a.d;
            if (b.v.lo >= a.v.hi) return b.d;
            return hull(a.d, b.d);
        case Op::PowInt: {
            const int n = static_cast<int>(value);
            return n == 0 ? Interval(0.0) : Interval(value) * powInt(a.v, n - 1) * a.d;
        }
        default:
            return Interval::entire();
    }
}

}  // namespace

void Tape::evalIntervalAlongRay(const Ray& ray, const Interval& t, Interval& f,
                                Interval& dfdt) const {
    thread_local std::vector<RaySlot> slots;
    const size_t n = mInstrs.size();
    if (slots.size() < n) slots.resize(n);  // grows once per thread, not per call
    RaySlot* s = slots.data();
    const IntervalDual none{Interval(), Interval()};
    for (size_t i = 0; i < n; ++i) {
        const TapeInstr& in = mInstrs[i];
        RaySlot& r = s[i];
        r.hasTrig = false;
        switch (in.op) {
            case Op::Const:
                r.v = Interval(in.value);
                r.d = Interval(0.0);
                break;
            case Op::VarX:
                alongAxis(ray.origin.x, ray.dir.x, t, r);
                break;
            case Op::VarY:
                alongAxis(ray.origin.y, ray.dir.y, t, r);
                break;
            case Op::VarZ:
                alongAxis(ray.origin.z, ray.dir.z, t, r);
                break;
            case Op::Sin:
            case Op::Cos: {
                RaySlot& a = s[in.a];
                if (!a.hasTrig) {
                    sinCos(a.v, a.sinV, a.cosV);
                    a.hasTrig = true;
                }
                if (in.op == Op::Sin) {
                    r.v = a.sinV;
                    r.d = scaledSlope(a.cosV, a);
                } else {
                    r.v = a.cosV;
                    r.d = -scaledSlope(a.sinV, a);
                }
                break;
            }
            case Op::Add:
                r.v = interval_kernel::add(s[in.a].v, s[in.b].v);
                r.d = sum(s[in.a].d, s[in.b].d);
                break;
            case Op::Sub:
                r.v = interval_kernel::sub(s[in.a].v, s[in.b].v);
                r.d = sum(s[in.a].d, -s[in.b].d);
                break;
            case Op::Mul: {
                const RaySlot &a = s[in.a], &b = s[in.b];
                r.v = interval_kernel::mul(a.v, b.v);
                r.d = sum(scaledSlope(b.v, a), scaledSlope(a.v, b));
                break;
            }
            default: {
                const IntervalDual& a = s[in.a];
                const IntervalDual& b =
                    in.b >= 0 ? static_cast<const IntervalDual&>(s[in.b]) : none;
                r.v = applyIntervalOp(in.op, a.v, b.v, in.value);
                r.d = slope(in.op, a, b, in.value, r.v);
            }
        }
        r.zeroSlope = isExactZero(r.d);
    }
    f = s[n - 1].v;
    dfdt = s[n - 1].d;
}

}  // namespace kerf
