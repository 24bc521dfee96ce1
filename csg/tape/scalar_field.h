/// @file csg/tape/scalar_field.h
/// @brief A scalar field defined outside the expression language that a tape can call
/// (Op::Field): a closed mesh's signed distance (mesh/mesh_shape.h). Every tape evaluator
/// calls one of these methods, so a field takes part in implicit forms, slices, displacement
/// and the octree like any other operation.
#pragma once

#include "csg/interval/interval.h"
#include "csg/types.h"

namespace kerf {

/// A field is shared by threads: its methods must be thread safe, and must not evaluate a tape
/// themselves (the evaluators' per-thread scratch is not reentrant).
class ScalarField {
public:
    virtual ~ScalarField() = default;
    /// f at p.
    virtual double value(const Vec3& p) const = 0;
    /// f at p for reference computations (at least as accurate as value()).
    virtual long double valueExtended(const glm::tvec3<long double>& p) const = 0;
    /// f at p (the same bits as value(p)) and a gradient there (a one-sided one where f has a
    /// kink).
    virtual double valueGradient(const Vec3& p, Vec3& gradient) const = 0;
    /// An interval holding f(p) for every p in the box.
    virtual Interval range(const Interval& x, const Interval& y, const Interval& z) const = 0;
    /// A bound on every partial derivative's magnitude, |∂f/∂x|, |∂f/∂y|, |∂f/∂z| ≤ lipschitz()
    /// everywhere (1 for a distance).
    virtual double lipschitz() const { return 1.0; }
    /// range() and an enclosure g of the gradient over the box, in the sense the mean-value
    /// form needs: f(p) − f(q) ∈ Σₖ g[k]·(pₖ − qₖ) for all p, q in the box. The default is
    /// [−L, L] on every axis (L = lipschitz()); a field that can prove more (e.g. that it is
    /// affine in the box) lets root isolation prove a root unique instead of bisecting.
    virtual Interval rangeGradient(const Interval& x, const Interval& y, const Interval& z,
                                   Interval g[3]) const {
        const double l = lipschitz();
        for (int k = 0; k < 3; ++k)
            g[k] = l >= 0.0 && l < kInf ? Interval(-l, l) : Interval::entire();
        return range(x, y, z);
    }
};

}  // namespace kerf
