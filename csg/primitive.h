/// @file csg/primitive.h
/// @brief The common base of the leaves of a solid tree. Each primitive has a process-unique
/// id that its boundaries carry (for statistics and deterministic tie-breaks).
#pragma once

#include "csg/node.h"
#include "csg/sphere_trace.h"

#include <algorithm>
#include <cmath>

namespace kerf {

uint32_t nextPrimitiveId();

class Primitive : public Node {
public:
    uint32_t id() const { return mId; }
    int primitiveCount() const override { return 1; }
    int depth() const override { return 1; }

protected:
    Primitive() : mId(nextPrimitiveId()) {}
    /// A simplified copy of a primitive (csg/prune.h) keeps its id: the same surface.
    explicit Primitive(uint32_t id) : mId(id) {}

    /// A boundary of this primitive at t with outward normal n (material left unset).
    Boundary boundary(double t, const Vec3& n) const {
        Boundary b;
        b.t = t;
        b.normal = n;
        b.primitive = mId;
        return b;
    }
    /// A boundary found by root isolation to the context's tolerance.
    Boundary rootBoundary(double t, const Vec3& n, const TraceContext& ctx) const {
        Boundary b = boundary(t, n);
        b.relError = static_cast<float>(ctx.relTolerance);
        return b;
    }

    /// An end of the searched range where the ray is inside: not a surface.
    static Boundary clipBoundary(double t) {
        Boundary b;
        b.t = t;
        return b;
    }

    /// TraceMethod::SphereTrace for a leaf whose implicit form value(p) is Lipschitz-1: marches
    /// it within the bounds, crossings taking normal(p) as their normal. Callers pass
    /// non-virtual calls. `unbounded` (a half-space): a range starting at −inf is marched from
    /// 0, where the comparison's rays start; else such a range is not traced.
    template <class Value, class Normal>
    void sphereTraceWithinBounds(const Value& value, const Normal& normal, const Ray& ray,
                                 double tmin, double tmax, TraceContext& ctx, SpanList& out,
                                 bool unbounded = false) const {
        double t0 = tmin, t1 = tmax;
        if (!mBounds.clipRay(ray, t0, t1)) return;
        // The ray comes from outside when it starts on the bounds (a half-space's is its plane).
        const bool outsideBefore = t0 > tmin;
        if (unbounded && !std::isfinite(t0)) t0 = std::min(0.0, t1);
        if (!std::isfinite(t0)) return;
        // The ray can start inside only at t0 == tmin, or at a start moved to 0 (unbounded):
        // either way the first span reaches back to tmin.
        sphereTraceSpans(value, ray, t0, t1, 1.0, outsideBefore, ctx,
                         [&](double t) { return rootBoundary(t, normal(ray.at(t)), ctx); },
                         [&](double t, bool atStart) { return clipBoundary(atStart ? tmin : t); },
                         out);
    }

private:
    uint32_t mId;
};

}  // namespace kerf
