/// @file csg/profiles/implicit_backed.h
/// @brief The base of the profile solids traced in closed form (the prism, the lathe) that
/// stand for an implicit extrusion or revolution: everything but ray tracing (values,
/// intervals, kind, parameters, slices, pruning, `kerf check`) is the implicit's.
#pragma once

#include "csg/primitives/closed_primitive.h"

#include <utility>

namespace kerf {

/// Derived provides closedSpans(const Ray&, SpanList&) (csg/primitives/closed_primitive.h).
template <class Derived>
class ImplicitBackedPrimitive : public ClosedFormPrimitive<Derived> {
public:
    explicit ImplicitBackedPrimitive(NodePtr implicitForm)
        : mImplicit(std::move(implicitForm)), mForm(static_cast<const Primitive&>(*mImplicit)) {
        this->mBounds = mImplicit->bounds();
    }

    double value(const Vec3& p) const override { return mImplicit->value(p); }
    long double valueExtended(const LVec3& p) const override { return mImplicit->valueExtended(p); }
    Interval valueInterval(const IntervalVec3& box) const override {
        return mImplicit->valueInterval(box);
    }
    NodeKind kind() const override { return mImplicit->kind(); }
    NodeParams params() const override { return mImplicit->params(); }
    ExprId implicitExpr(ExprGraph& g, ExprId x, ExprId y, ExprId z) const override {
        return mForm.implicitExpr(g, x, y, z);
    }
    const Tape* compiledForm() const override { return mForm.compiledForm(); }
    double lipschitz() const override { return mForm.lipschitz(); }

private:
    NodePtr mImplicit;
    const Primitive& mForm;
};

}  // namespace kerf
