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
#include "csg/tape.h"
#include "csg/tape_ray_step.h"

namespace kerf {

using namespace ray_step;

void Tape::evalIntervalAlongRay(const Ray& ray, const Interval& t, Interval& f,
                                Interval& dfdt) const {
    thread_local std::vector<RaySlot> slots;
    const size_t n = mInstrs.size();
    if (slots.size() < n) slots.resize(n);  // grows once per thread, not per call
    RaySlot* s = slots.data();
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
            default:
                evalStep(in.op, in.a, in.b, in.value, s, r);
        }
        r.zeroSlope = isExactZero(r.d);
    }
    f = s[n - 1].v;
    dfdt = s[n - 1].d;
}

}  // namespace kerf
