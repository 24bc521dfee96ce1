// The implicit primitive {f ≤ 0} ∩ box: spans by interval root isolation of the tape along the
// ray, clipped to the box; where the box cuts the inside region, the box face is the boundary.
#include <algorithm>
#include <mutex>

#include "csg/primitives/comparison_methods.h"
#include "csg/primitives/root_isolation.h"
#include "csg/tape/tape_along_ray.h"
#include "csg/tape/tape_ray_program.h"
#include "csg/tree/solids.h"

namespace kerf {
namespace {

/// f along the ray for the comparison-only interval method on a stand-in
/// (csg/primitives/comparison_methods.h): enclosures, point values and slopes from the tape
/// specialised to the ray (csg/tape/tape_ray_program.h). (A centred form, f(m) + f'([a, b])·([a, b]
/// − m) intersected with the enclosure, was tried here and measured: it changed no classification
/// on the accuracy scenes, whose enclosures are already tight, and cost a second evaluation per
/// call.)
struct ProgramAlongRay {
    const Tape& tape;
    const Ray& ray;
    TapeRayProgram& program;

    void range(double a, double b, Interval& f, Interval& dfdt) const {
        program.eval(Interval(a, b), f, dfdt);
    }
    double value(double t) const { return program.value(t); }
    double valueAndSlope(double t, double& dfdt) const { return program.valueAndSlope(t, dfdt); }
};

class Implicit final : public Primitive {
public:
    Implicit(std::shared_ptr<const Tape> f, const Bounds3& box) : mTape(std::move(f)) {
        mBounds = box;
    }
    /// A copy of primitive `id` with another function (csg/tree/prune.h) or a stand-in for it
    /// (csg/primitives/comparison_methods.h): its boundaries carry that id.
    Implicit(std::shared_ptr<const Tape> f, const Bounds3& box, uint32_t id, bool standIn = false)
        : Primitive(id), mTape(std::move(f)) {
        mBounds = box;
        // A stand-in for a primitive whose form calls a field (a mesh) or noise has no plan:
        // it keeps the tape's own evaluation along the ray, as implicits do.
        if (standIn && TapeRayPlan::accepts(*mTape)) mPlan = std::make_unique<TapeRayPlan>(*mTape);
    }

    void spans(const Ray& ray, double tmin, double tmax, TraceContext& ctx,
               SpanList& out) const override {
        // The closed method already isolates f by intervals: Interval is the same.
        if (ctx.method == TraceMethod::SphereTrace)
            return comparisonSpans(*this, ray, tmin, tmax, ctx, out);
        out.clear();
        ++ctx.stats.primitiveTests;
        Range r;
        if (!clip(ray, tmin, tmax, r)) return;
        if (mPlan) {
            ProgramAlongRay problem{*mTape, ray, preparedProgram(ray)};
            return isolatedSpansOf(problem, ray, r, ctx, out);
        }
        TapeAlongRay problem{*mTape, ray};
        isolatedSpansOf(problem, ray, r, ctx, out);
    }

    /// The same crossings as spans(), but the search stops once the first surface is decided:
    /// rays that need only the nearest hit skip every later crossing.
    bool firstSurface(const Ray& ray, double tmin, double tmax, TraceContext& ctx, Boundary& hit,
                      bool& entering) const override {
        if (ctx.method == TraceMethod::SphereTrace)
            return Node::firstSurface(ray, tmin, tmax, ctx, hit, entering);
        ++ctx.stats.primitiveTests;
        Range r;
        if (!clip(ray, tmin, tmax, r)) return false;
        if (mPlan) {
            ProgramAlongRay problem{*mTape, ray, preparedProgram(ray)};
            return firstSurfaceOf(problem, ray, r, tmin, tmax, ctx, hit, entering);
        }
        TapeAlongRay problem{*mTape, ray};
        return firstSurfaceOf(problem, ray, r, tmin, tmax, ctx, hit, entering);
    }

    double value(const Vec3& p) const override {
        const Vec3 outside = glm::max(mBounds.lo - p, p - mBounds.hi);
        return std::max(mTape->eval(p), std::max(outside.x, std::max(outside.y, outside.z)));
    }

    long double valueExtended(const LVec3& p) const override {
        long double outside = -INFINITY;
        for (int a = 0; a < 3; ++a)
            outside = std::max(
                {outside, (long double)mBounds.lo[a] - p[a], p[a] - (long double)mBounds.hi[a]});
        return std::max(mTape->evalExtended(p), outside);
    }

    Interval valueInterval(const IntervalVec3& box) const override {
        const Interval f = mTape->evalInterval(box.x, box.y, box.z);
        const Interval* axes[3] = {&box.x, &box.y, &box.z};
        Interval outside(-kInf);
        for (int a = 0; a < 3; ++a)
            outside = max(outside, max(Interval(mBounds.lo[a]) - *axes[a],
                                       *axes[a] - Interval(mBounds.hi[a])));
        return max(f, outside);
    }

    NodeKind kind() const override { return NodeKind::Implicit; }
    NodeParams params() const override { return ImplicitParams{mTape, mBounds}; }

    /// The tape's instructions over the given coordinates (the bound is not part of it).
    ExprId implicitExpr(ExprGraph& g, ExprId x, ExprId y, ExprId z) const override {
        std::vector<ExprId> slot(mTape->size());
        for (int i = 0; i < mTape->size(); ++i) {
            const TapeInstr& in = mTape->instrs()[i];
            switch (in.op) {
                case Op::Const: slot[i] = g.constant(in.value); break;
                case Op::VarX: slot[i] = x; break;
                case Op::VarY: slot[i] = y; break;
                case Op::VarZ: slot[i] = z; break;
                case Op::PowInt: slot[i] = g.powInt(slot[in.a], static_cast<int>(in.value)); break;
                case Op::Noise:
                    slot[i] = g.noise(slot[in.a], slot[in.b], slot[in.c], noiseSeed(in));
                    break;
                case Op::Field:  // the graph gives the field its own index
                    slot[i] = g.field(slot[in.a], slot[in.b], slot[in.c],
                                      mTape->fields()[fieldIndex(in)]);
                    break;
                default:
                    slot[i] = in.b >= 0 ? g.binary(in.op, slot[in.a], slot[in.b])
                                        : g.unary(in.op, slot[in.a]);
            }
        }
        return slot.back();
    }

    const Tape* compiledForm() const override { return mTape.get(); }

    /// For sphere tracing only: an ESTIMATE, made on first use so that pruned copies and
    /// renders that never sphere trace do not pay for its 4096 gradient samples.
    double lipschitz() const override {
        std::call_once(mLipschitzOnce, [this] { mLipschitz = estimateLipschitz(); });
        return mLipschitz;
    }

private:
    /// The part of the caller's range inside the box, and whether its ends are box faces.
    struct Range {
        double t0, t1;
        bool startOnBox, endOnBox;
    };

    /// Spans from every crossing of p (f along the ray) on the clipped range.
    template <typename P>
    void isolatedSpansOf(P& problem, const Ray& ray, const Range& r, TraceContext& ctx,
                         SpanList& out) const {
        isolatedSpans(
            problem, r.t0, r.t1, 0.0, ctx,
            [&](double t) { return rootBoundary(t, surfaceNormal(ray, t, ctx), ctx); },
            [&](bool atStart) { return endBoundary(ray, r, atStart); }, out);
    }

    template <typename P>
    bool firstSurfaceOf(P& problem, const Ray& ray, const Range& r, double tmin, double tmax,
                        TraceContext& ctx, Boundary& hit, bool& entering) const {
        FirstSurfaceTracker tracker(tmin, tmax, ctx.relTolerance);
        tracker.search(
            problem, r.t0, r.t1, 0.0, ctx,
            [&](double t) { return rootBoundary(t, surfaceNormal(ray, t, ctx), ctx); },
            [&](bool atStart) { return endBoundary(ray, r, atStart); },
            [](double tNext) { return tNext; });
        return tracker.result(hit, entering);
    }

    /// This thread's program for the stand-in's tape, specialised to `ray`. One per thread:
    /// a search does not start another before it ends.
    TapeRayProgram& preparedProgram(const Ray& ray) const {
        thread_local TapeRayProgram program;
        program.prepare(*mPlan, ray);
        return program;
    }
    bool clip(const Ray& ray, double tmin, double tmax, Range& r) const {
        double boxIn = -kInf, boxOut = kInf;
        if (!mBounds.clipRay(ray, boxIn, boxOut)) return false;
        r = {std::max(boxIn, tmin), std::min(boxOut, tmax), boxIn >= tmin, boxOut <= tmax};
        // An unbounded range cannot be bisected; the language always gives a finite box.
        return r.t0 <= r.t1 && std::isfinite(r.t0) && std::isfinite(r.t1);
    }

    /// For sphere tracing only: an ESTIMATE of the Lipschitz constant of value(), as POV-Ray
    /// users set max_gradient: the largest |∇f| on a 16³ grid over the box, times 1.5, and at
    /// least 1 (the box term). Not a bound: f can be steeper between the samples, and that is
    /// where sphere tracing steps over the surface.
    double estimateLipschitz() const {
        if (!mBounds.finite()) return 1.0;
        constexpr int kSamples = 16;
        double maxGradient = 0.0;
        for (int i = 0; i < kSamples; ++i)
            for (int j = 0; j < kSamples; ++j)
                for (int k = 0; k < kSamples; ++k) {
                    const Vec3 w = Vec3(i, j, k) / double(kSamples - 1);
                    Vec3 g;
                    mTape->evalGradient(mBounds.lo + w * mBounds.extent(), g);
                    const double n = glm::length(g);
                    if (n > maxGradient) maxGradient = n;  // NaN samples are skipped
                }
        return std::max(1.0, 1.5 * maxGradient);
    }

    /// The normal at a crossing, unless the caller needs only where crossings are.
    Vec3 surfaceNormal(const Ray& ray, double t, const TraceContext& ctx) const {
        return ctx.occlusionOnly ? Vec3(0.0) : normalAt(ray.at(t));
    }

    Vec3 normalAt(const Vec3& p) const {
        Vec3 g;
        mTape->evalGradient(p, g);
        return g;
    }

    /// The boundary where the clipped range starts (entering) or ends while inside f: the box
    /// face the ray crosses there, or a clip of the caller's range (primitive 0).
    Boundary endBoundary(const Ray& ray, const Range& r, bool entering) const {
        const double t = entering ? r.t0 : r.t1;
        if (!(entering ? r.startOnBox : r.endOnBox)) return clipBoundary(t);
        // The face is on the axis whose slab gives the latest entry / earliest exit.
        int axis = 0;
        double best = entering ? -kInf : kInf;
        for (int a = 0; a < 3; ++a) {
            const double d = ray.dir[a];
            if (d == 0.0) continue;
            const double plane = (d > 0.0) == entering ? mBounds.lo[a] : mBounds.hi[a];
            const double ta = (plane - ray.origin[a]) / d;
            if (entering ? ta > best : ta < best) best = ta, axis = a;
        }
        Vec3 n(0.0);
        n[axis] = (ray.dir[axis] > 0.0) == entering ? -1.0 : 1.0;
        return boundary(t, n);
    }

    std::shared_ptr<const Tape> mTape;
    /// Only for a comparison method's stand-in for a primitive
    /// (csg/primitives/comparison_methods.h): isolation then runs on TapeRayProgram enclosures
    /// instead of Tape::evalIntervalAlongRay.
    std::unique_ptr<const TapeRayPlan> mPlan;
    mutable std::once_flag mLipschitzOnce;
    mutable double mLipschitz = 1.0;  ///< estimated, for TraceMethod::SphereTrace only
};

}  // namespace

NodePtr makeImplicit(std::shared_ptr<const Tape> f, const Bounds3& bound) {
    return std::make_shared<Implicit>(std::move(f), bound);
}

NodePtr withImplicitFunction(const Node& original, std::shared_ptr<const Tape> f) {
    // An implicit, or a primitive that takes its implicit form from one (csg/profiles/prism.h).
    const auto& o = dynamic_cast<const Primitive&>(original);
    return std::make_shared<Implicit>(std::move(f), o.bounds(), o.id());
}

NodePtr makeImplicitStandIn(std::shared_ptr<const Tape> f, const Bounds3& bound, uint32_t id) {
    return std::make_shared<Implicit>(std::move(f), bound, id, true);
}

}  // namespace kerf
