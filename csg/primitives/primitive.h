/// @file csg/primitives/primitive.h
/// @brief The common base of the leaves of a solid tree. Each primitive has a process-unique
/// id that its boundaries carry (for statistics and deterministic tie-breaks), and gives its
/// implicit form as an expression, from which the comparison methods
/// (csg/primitives/comparison_methods.h) trace it.
#pragma once

#include "csg/tape/expr.h"
#include "csg/tree/node.h"

#include <memory>

namespace kerf {

class Tape;
uint32_t nextPrimitiveId();

class Primitive : public Node {
public:
    uint32_t id() const { return mId; }

    /// The implicit form f over the coordinates x, y, z of this primitive's space, built into
    /// g: the solid is {f ≤ 0} ∩ bounds(). It is value() itself, except for an implicit, whose
    /// value() adds its bound's term.
    virtual ExprId implicitExpr(ExprGraph& g, ExprId x, ExprId y, ExprId z) const = 0;
    /// A bound on |∇value()| for sphere tracing: 1 for the distance-like forms (an implicit's
    /// is estimated, not proven).
    virtual double lipschitz() const { return 1.0; }
    /// The implicit form already compiled, if the primitive holds it (an implicit), else null.
    virtual const Tape* compiledForm() const { return nullptr; }

    /// The three evaluations default to implicitExpr() compiled once to a tape, so a new
    /// primitive writes its formula once. The older leaves override them with hand-written
    /// forms; tests/csg/derived_values_test.cpp checks each against the derived ones.
    double value(const Vec3& p) const override { return derivedValue(p); }
    long double valueExtended(const LVec3& p) const override { return derivedValueExtended(p); }
    Interval valueInterval(const IntervalVec3& box) const override {
        return derivedValueInterval(box);
    }
    /// The evaluations of implicitExpr() through its tape, whatever the overrides.
    double derivedValue(const Vec3& p) const;
    long double derivedValueExtended(const LVec3& p) const;
    Interval derivedValueInterval(const IntervalVec3& box) const;

protected:
    Primitive() : mId(nextPrimitiveId()) {}
    /// A copy or stand-in of another primitive (csg/tree/prune.h,
    /// csg/primitives/comparison_methods.h) keeps its id: the same surface.
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

private:
    /// implicitExpr() compiled on first use; compiled twice at worst when two threads race.
    const Tape& derivedTape() const;

    uint32_t mId;
    mutable std::shared_ptr<const Tape> mDerivedTape;  ///< read and set atomically
};

}  // namespace kerf
