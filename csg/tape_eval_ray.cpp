// Interval evaluation along a ray with the derivative in t: forward-mode differentiation on
// intervals. Each slot holds an enclosure of the value and one of d/dt over the t-interval.
// Where an operation is not differentiable or not continuous on the enclosure (abs or min/max
// at a kink, floor/ceil at a jump), the derivative enclosure is widened to hold every one-sided
// slope (kinks) or made entire (jumps), so "0 ∉ df/dt" still proves strict monotonicity.
#include "csg/interval_ops.h"
#include "csg/tape.h"

namespace kerf {
namespace {

struct IntervalDual {
    Interval v;
    Interval d;
};

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
    thread_local std::vector<IntervalDual> slots;
    slots.resize(mInstrs.size());
    IntervalDual* s = slots.data();
    const IntervalDual none{Interval(), Interval()};
    for (size_t i = 0; i < mInstrs.size(); ++i) {
        const TapeInstr& in = mInstrs[i];
        switch (in.op) {
            case Op::Const:
                s[i] = {Interval(in.value), Interval(0.0)};
                break;
            case Op::VarX:
                s[i] = {Interval(ray.origin.x) + t * Interval(ray.dir.x), Interval(ray.dir.x)};
                break;
            case Op::VarY:
                s[i] = {Interval(ray.origin.y) + t * Interval(ray.dir.y), Interval(ray.dir.y)};
                break;
            case Op::VarZ:
                s[i] = {Interval(ray.origin.z) + t * Interval(ray.dir.z), Interval(ray.dir.z)};
                break;
            default: {
                const IntervalDual& a = s[in.a];
                const IntervalDual& b = in.b >= 0 ? s[in.b] : none;
                const Interval v = applyIntervalOp(in.op, a.v, b.v, in.value);
                s[i] = {v, slope(in.op, a, b, in.value, v)};
            }
        }
    }
    f = s[mInstrs.size() - 1].v;
    dfdt = s[mInstrs.size() - 1].d;
}

}  // namespace kerf
