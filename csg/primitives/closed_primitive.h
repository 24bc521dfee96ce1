/// @file csg/primitives/closed_primitive.h
/// @brief The base of the primitives with closed-form spans (sphere, box, cylinder, cone,
/// half-space): one spans() that runs the closed form without a virtual call (CRTP), and
/// hands the comparison methods to csg/primitives/comparison_methods.h.
#pragma once

#include "csg/primitives/comparison_methods.h"

namespace kerf {

/// Derived (final) provides, callable from here (it befriends this base):
///   void closedSpans(const Ray&, SpanList&) const;  the closed form (TraceMethod::Closed)
/// and, as every primitive, implicitExpr().
template <class Derived>
class ClosedFormPrimitive : public Primitive {
public:
    void spans(const Ray& ray, double tmin, double tmax, TraceContext& ctx,
               SpanList& out) const final {
        // One predictable branch: the comparison methods are never mixed with the default.
        if (ctx.method != TraceMethod::Closed)
            return comparisonSpans(*this, ray, tmin, tmax, ctx, out);
        out.clear();
        ++ctx.stats.primitiveTests;
        static_cast<const Derived&>(*this).closedSpans(ray, out);
    }

    bool firstSurface(const Ray& ray, double tmin, double tmax, TraceContext& ctx, Boundary& hit,
                      bool& entering) const override {
        if (ctx.method != TraceMethod::Closed)
            return comparisonFirstSurface(*this, ray, tmin, tmax, ctx, hit, entering);
        return Node::firstSurface(ray, tmin, tmax, ctx, hit, entering);
    }
};

}  // namespace kerf
