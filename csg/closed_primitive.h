/// @file csg/closed_primitive.h
/// @brief The base of the primitives with closed-form spans (sphere, box, cylinder, cone,
/// half-space): one spans() that picks the trace method, without virtual calls (CRTP).
#pragma once

#include "csg/primitive.h"

namespace kerf {

/// Derived (final) provides, callable from here (it befriends this base):
///   void closedSpans(const Ray&, SpanList&) const;  the closed form (TraceMethod::Closed)
///   void intervalSpans(const Ray&, double tmin, double tmax, TraceContext&, SpanList&) const;
///   Vec3 gradient(const Vec3& p) const;  the normal a sphere-traced crossing at p gets
/// and a Lipschitz-1 value(). `kUnbounded` (false here) may be redeclared true by a primitive
/// without finite bounds (see Primitive::sphereTraceWithinBounds).
template <class Derived>
class ClosedFormPrimitive : public Primitive {
public:
    void spans(const Ray& ray, double tmin, double tmax, TraceContext& ctx,
               SpanList& out) const final {
        out.clear();
        ++ctx.stats.primitiveTests;
        const Derived& self = static_cast<const Derived&>(*this);
        if (ctx.method == TraceMethod::Interval)
            return self.intervalSpans(ray, tmin, tmax, ctx, out);
        if (ctx.method == TraceMethod::SphereTrace) {
            return sphereTraceWithinBounds(
                [&self](const Vec3& p) { return self.Derived::value(p); },
                [&self](const Vec3& p) { return self.gradient(p); }, ray, tmin, tmax, ctx, out,
                Derived::kUnbounded);
        }
        self.closedSpans(ray, out);
    }

protected:
    static constexpr bool kUnbounded = false;
};

}  // namespace kerf
