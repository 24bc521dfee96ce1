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
//
// Tapes made only of ops that never raise a NaN flag (Tape::finish) take a lean path that keeps
// no flags and runs the same kernels, so it gives the same bits as the general one.
#include "csg/interval/interval_trig.h"
#include "csg/tape/noise.h"
#include "csg/tape/scalar_field.h"
#include "csg/tape/tape.h"
#include "csg/tape/tape_ray_step.h"

namespace kerf {

using namespace ray_step;

namespace {

/// A slot of the lean path: the same value and slope enclosures as RaySlot without NaN flags
/// (the lean tapes never raise one), with sin and cos of the value cached as RaySlot does.
struct LeanSlot {
    double lo, hi, dlo, dhi;
    bool zeroSlope, hasTrig;
    double slo, shi, clo, chi;
};

/// The general path's arithmetic on flagless operands: each kernel is the same inline
/// function with a constant false flag, so the results are the same bits (tested).
[[gnu::always_inline]] inline Interval value(const LeanSlot& a) { return {a.lo, a.hi}; }
[[gnu::always_inline]] inline Interval slopeOf(const LeanSlot& a) { return {a.dlo, a.dhi}; }
[[gnu::always_inline]] inline void store(LeanSlot& r, const Interval& v, const Interval& d) {
    r.lo = v.lo, r.hi = v.hi, r.dlo = d.lo, r.dhi = d.hi;
}
/// k·a's slope, exactly 0 when a's slope is (scaledSlope).
[[gnu::always_inline]] inline Interval leanScaledSlope(const Interval& k, const LeanSlot& a) {
    return a.zeroSlope ? Interval(0.0) : interval_kernel::mul(k, slopeOf(a));
}

/// Tape::evalIntervalAlongRay for a tape whose every op is in Tape::finish's lean list and a
/// t without a NaN flag: no flag can arise, so none is kept.
void evalLean(const std::vector<TapeInstr>& instrs, const Ray& ray, const Interval& t, Interval& f,
              Interval& dfdt) {
    using namespace interval_kernel;
    thread_local std::vector<LeanSlot> slots;
    const size_t n = instrs.size();
    if (slots.size() < n) slots.resize(n);
    LeanSlot* s = slots.data();
    const double origin[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
    const double dir[3] = {ray.dir.x, ray.dir.y, ray.dir.z};
    for (size_t i = 0; i < n; ++i) {
        const TapeInstr& in = instrs[i];
        LeanSlot& r = s[i];
        r.hasTrig = false;
        switch (in.op) {
            case Op::Const: store(r, Interval(in.value), Interval(0.0)); break;
            case Op::VarX:
            case Op::VarY:
            case Op::VarZ: {
                RaySlot axis;
                const int k = static_cast<int>(in.op) - static_cast<int>(Op::VarX);
                alongAxis(origin[k], dir[k], t, axis);
                store(r, axis.v, axis.d);
                break;
            }
            case Op::Sin:
            case Op::Cos: {
                LeanSlot& a = s[in.a];
                if (!a.hasTrig) {
                    Interval sv, cv;
                    if (!interval_trig::trySinCosFast(value(a), sv, cv)) sinCos(value(a), sv, cv);
                    a.slo = sv.lo, a.shi = sv.hi, a.clo = cv.lo, a.chi = cv.hi;
                    a.hasTrig = true;
                }
                if (in.op == Op::Sin)
                    store(r, {a.slo, a.shi}, leanScaledSlope({a.clo, a.chi}, a));
                else
                    store(r, {a.clo, a.chi}, -leanScaledSlope({a.slo, a.shi}, a));
                break;
            }
            case Op::Add:
                store(r, add(value(s[in.a]), value(s[in.b])),
                      sum(slopeOf(s[in.a]), slopeOf(s[in.b])));
                break;
            case Op::Sub:
                store(r, sub(value(s[in.a]), value(s[in.b])),
                      sum(slopeOf(s[in.a]), -slopeOf(s[in.b])));
                break;
            case Op::Mul: {
                const LeanSlot &a = s[in.a], &b = s[in.b];
                store(r, mul(value(a), value(b)),
                      sum(leanScaledSlope(value(b), a), leanScaledSlope(value(a), b)));
                break;
            }
            case Op::Neg: store(r, -value(s[in.a]), -slopeOf(s[in.a])); break;
            default: {  // Op::Square, as the general path's slope(): (2·a)·a'
                const LeanSlot& a = s[in.a];
                store(r, sqr(value(a)), mul(mul(Interval(2.0), value(a)), slopeOf(a)));
            }
        }
        r.zeroSlope = r.dlo == 0.0 && r.dhi == 0.0;
    }
    f = value(s[n - 1]);
    dfdt = slopeOf(s[n - 1]);
}

}  // namespace

void Tape::evalIntervalAlongRay(const Ray& ray, const Interval& t, Interval& f,
                                Interval& dfdt) const {
    if (mLeanAlongRay && !t.maybeNan) return evalLean(mInstrs, ray, t, f, dfdt);
    evalIntervalAlongRayReference(ray, t, f, dfdt);
}

void Tape::evalIntervalAlongRayReference(const Ray& ray, const Interval& t, Interval& f,
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
            case Op::VarX: alongAxis(ray.origin.x, ray.dir.x, t, r); break;
            case Op::VarY: alongAxis(ray.origin.y, ray.dir.y, t, r); break;
            case Op::VarZ: alongAxis(ray.origin.z, ray.dir.z, t, r); break;
            case Op::Noise: {
                const RaySlot &a = s[in.a], &b = s[in.b], &c = s[in.c];
                Interval g[3];
                r.v = gradientNoiseRange(a.v, b.v, c.v, noiseSeed(in), g);
                r.d = scaledSlope(g[0], a) + scaledSlope(g[1], b) + scaledSlope(g[2], c);
                break;
            }
            case Op::Field: {
                // The chain rule through the field's gradient enclosure over the box: [−L, L]
                // per axis unless the field proves more (ScalarField::rangeGradient).
                const RaySlot &a = s[in.a], &b = s[in.b], &c = s[in.c];
                Interval g[3];
                r.v = this->field(in).rangeGradient(a.v, b.v, c.v, g);
                r.d = scaledSlope(g[0], a) + scaledSlope(g[1], b) + scaledSlope(g[2], c);
                break;
            }
            default: evalStep(in.op, in.a, in.b, in.value, s, r);
        }
        r.zeroSlope = isExactZero(r.d);
    }
    f = s[n - 1].v;
    dfdt = s[n - 1].d;
}

}  // namespace kerf
