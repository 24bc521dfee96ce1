// The comparison-only trace methods over a primitive's implicit form: interval isolation by
// a stand-in implicit primitive, and sphere tracing of value().
#include "csg/primitives/comparison_methods.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <variant>

#include "csg/primitives/sphere_trace.h"
#include "csg/tree/solids.h"

namespace kerf {
namespace {

/// p's bounds widened by 2⁻²⁰ of their size: the solid then lies strictly inside, so every
/// surface (a box's faces too) is a root of the form, found and polished as such, never an
/// end of the clipped range.
Bounds3 widened(const Bounds3& b) {
    Bounds3 w = b;
    for (int a = 0; a < 3; ++a) {
        const double extent = b.hi[a] - b.lo[a];  // inf on a half-open axis (half-spaces)
        const double size = std::isfinite(extent) ? extent : 0.0;
        if (std::isfinite(b.lo[a])) w.lo[a] -= 0x1p-20 * (std::fabs(b.lo[a]) + size);
        if (std::isfinite(b.hi[a])) w.hi[a] += 0x1p-20 * (std::fabs(b.hi[a]) + size);
    }
    return w;
}

/// Stand-ins kept per thread before the cache starts over (they are cheap to rebuild).
constexpr size_t kMaxStandIns = size_t(1) << 16;

/// The implicit primitive equal to p: p's form over p's (widened) bounds, carrying p's id.
/// One per thread and primitive (ids are never reused), built on first use. The cache is
/// cleared only when a new entry is made, so a stand-in stays valid while its primitive's
/// trace asks for it again.
const Node& standIn(const Primitive& p) {
    thread_local std::unordered_map<uint32_t, NodePtr> cache;
    auto found = cache.find(p.id());
    if (found != cache.end()) return *found->second;
    if (cache.size() >= kMaxStandIns) cache.clear();
    ExprGraph g;
    const ExprId f = p.implicitExpr(g, g.x(), g.y(), g.z());
    NodePtr& node = cache[p.id()];
    node = makeImplicitStandIn(Tape::compile(g, f), widened(p.bounds()), p.id());
    return *node;
}

/// Over [t, ±inf) (towards `up` or down) the tape along the ray keeps the state it has at t:
/// its enclosure there has one sign, or it is monotone away from zero.
bool settledBeyond(const Tape& f, const Ray& ray, double t, bool up) {
    Interval v, slope;
    f.evalIntervalAlongRay(ray, up ? Interval(t, kInf) : Interval(-kInf, t), v, slope);
    if (v.classify() != Classification::Ambiguous) return true;
    if (slope.maybeNan || slope.containsZero()) return false;
    const bool inside = isInside(f.eval(ray.at(t)));
    const bool rising = (slope.lo > 0.0) == up;  // f grows moving away from t
    return inside != rising;                     // outside and rising, or inside and falling
}

/// A finite replacement for an infinite end of the range, past which nothing changes: the
/// finite `base` moved outward by doubling steps (at most to ±2^1020).
double finiteEnd(const Tape& f, const Ray& ray, double base, bool up) {
    double reach = std::max(1.0, std::fabs(base));
    for (;;) {
        const double t = up ? base + reach : base - reach;
        if (reach >= 0x1p1020 || settledBeyond(f, ray, t, up)) return t;
        reach *= 2.0;
    }
}

/// The stand-in and the finite range [a, b] it searches for p over [tmin, tmax]; false when
/// the ray misses p's bounds there.
bool intervalRange(const Primitive& p, const Ray& ray, double tmin, double tmax, const Node*& node,
                   double& a, double& b) {
    node = &standIn(p);
    double c0 = tmin, c1 = tmax;
    if (!node->bounds().clipRay(ray, c0, c1)) return false;
    // Root isolation needs a finite range: infinite ends the bounds leave open become
    // finite ones beyond which the state is proven constant, and clips there go back out.
    a = tmin, b = tmax;
    if (!(std::isfinite(c0) && std::isfinite(c1))) {
        const Tape& f = implicitTape(p);
        const double base = std::isfinite(c0) ? c0 : std::isfinite(c1) ? c1 : 0.0;
        if (!std::isfinite(c0)) a = finiteEnd(f, ray, std::min(base, c1), false);
        if (!std::isfinite(c1)) b = finiteEnd(f, ray, std::max(base, a), true);
    }
    return true;
}

void intervalSpans(const Primitive& p, const Ray& ray, double tmin, double tmax, TraceContext& ctx,
                   SpanList& out) {
    const Node* node;
    double a, b;
    if (!intervalRange(p, ray, tmin, tmax, node, a, b)) {
        out.clear();
        ++ctx.stats.primitiveTests;
        return;
    }
    node->spans(ray, a, b, ctx, out);
    for (Span& s : out) {
        if (!s.in.isSurface() && s.in.t == a) s.in.t = tmin;
        if (!s.out.isSurface() && s.out.t == b) s.out.t = tmax;
    }
}

/// The outward normal of the bounds' face the ray crosses at an end of its clipped range.
Vec3 boundsFace(const Bounds3& box, const Ray& ray, bool entering) {
    int axis = 0;
    double best = entering ? -kInf : kInf;
    for (int a = 0; a < 3; ++a) {
        const double d = ray.dir[a];
        if (d == 0.0) continue;
        const double plane = (d > 0.0) == entering ? box.lo[a] : box.hi[a];
        const double ta = (plane - ray.origin[a]) / d;
        if (entering ? ta > best : ta < best) best = ta, axis = a;
    }
    Vec3 n(0.0);
    n[axis] = (ray.dir[axis] > 0.0) == entering ? -1.0 : 1.0;
    return n;
}

void sphereTraceSpans(const Primitive& p, const Ray& ray, double tmin, double tmax,
                      TraceContext& ctx, SpanList& out) {
    out.clear();
    ++ctx.stats.primitiveTests;
    const Bounds3& box = p.bounds();
    double t0 = tmin, t1 = tmax;
    if (!box.clipRay(ray, t0, t1)) return;
    // The ray comes from outside when it starts on the bounds (a half-space's is its plane).
    const bool outsideBefore = t0 > tmin, endOnBounds = t1 < tmax;
    // An unbounded range (half-spaces) is marched from 0, where the comparison's rays start.
    if (!box.finite() && !std::isfinite(t0)) t0 = std::min(0.0, t1);
    if (!std::isfinite(t0)) return;
    const Tape& f = implicitTape(p);
    const auto surface = [&](double t) {
        Boundary b;
        b.t = t;
        b.primitive = p.id();
        b.relError = static_cast<float>(ctx.relTolerance);
        const Vec3 q = ray.at(t);
        f.evalGradient(q, b.normal);
        // Where the bounds cut the solid (an implicit's box) the surface is the box face.
        const Vec3 outside = glm::max(box.lo - q, q - box.hi);
        if (std::max(outside.x, std::max(outside.y, outside.z)) > f.eval(q))
            b.normal = boundsFace(box, ray, glm::dot(b.normal, ray.dir) < 0.0);
        return b;
    };
    const auto end = [&](double t, bool atStart) {
        Boundary b;
        b.t = atStart ? tmin : t;
        // Still inside where the range leaves the bounds: the bounds' face is the surface.
        if (!atStart && endOnBounds && t == t1) {
            b.primitive = p.id();
            b.normal = boundsFace(box, ray, false);
        }
        return b;
    };
    kerf::sphereTraceSpans([&p](const Vec3& q) { return p.value(q); }, ray, t0, t1, p.lipschitz(),
                           outsideBefore, ctx, surface, end, out);
}

}  // namespace

const Tape& implicitTape(const Primitive& p) {
    if (const Tape* own = p.compiledForm()) return *own;
    // Through the stand-in's own pointer: no shared_ptr copy (an atomic count) per call.
    return *static_cast<const Primitive&>(standIn(p)).compiledForm();
}

void comparisonSpans(const Primitive& p, const Ray& ray, double tmin, double tmax,
                     TraceContext& ctx, SpanList& out) {
    if (ctx.method == TraceMethod::SphereTrace)
        return sphereTraceSpans(p, ray, tmin, tmax, ctx, out);
    intervalSpans(p, ray, tmin, tmax, ctx, out);
}

bool comparisonFirstSurface(const Primitive& p, const Ray& ray, double tmin, double tmax,
                            TraceContext& ctx, Boundary& hit, bool& entering) {
    if (ctx.method == TraceMethod::SphereTrace)
        return p.Node::firstSurface(ray, tmin, tmax, ctx, hit, entering);
    // The stand-in's own first-surface search: it stops once the first surface is decided.
    // Only surface boundaries come out, so the finite range needs no clips put back.
    const Node* node;
    double a, b;
    if (!intervalRange(p, ray, tmin, tmax, node, a, b)) {
        ++ctx.stats.primitiveTests;
        return false;
    }
    return node->firstSurface(ray, a, b, ctx, hit, entering);
}

}  // namespace kerf
