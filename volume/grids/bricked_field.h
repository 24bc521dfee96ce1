/// @file volume/grids/bricked_field.h
/// @brief A scalar field sampled once on a grid over a box and stored in a BrickGrid<float>
/// (volume/grids/brick_grid.h): mist density baked from an expression, caches of sampled implicits.
/// Between samples the field is the trilinear interpolant of the stored values; beyond the
/// grid it is extended constant from the nearest edge (continuous, so lipschitz() holds
/// everywhere).
#pragma once

#include <functional>
#include <memory>

#include "csg/tape/scalar_field.h"
#include "csg/types.h"
#include "volume/grids/brick_grid.h"

namespace kerf {

class BrickedField final : public ScalarField {
public:
    /// Sample (i, j, k) of the grid sits at origin + spacing·(i, j, k); spacing > 0.
    BrickedField(BrickGrid<float> grid, Vec3 origin, double spacing);

    /// The trilinear interpolant at p (NaN for a NaN coordinate).
    double value(const Vec3& p) const override;
    /// The same interpolant of the same stored values, in long double.
    long double valueExtended(const glm::tvec3<long double>& p) const override;
    /// value(p) and the interpolant's gradient (of the cell of the floor on a cell face; 0
    /// along an axis where p is beyond the grid).
    double valueGradient(const Vec3& p, Vec3& gradient) const override;
    /// Holds value(p) for every p in the box: the min/max of the stored values of every cell
    /// the box meets (bounded by whole bricks: volume/grids/brick_grid.h), widened by a bound on
    /// the rounding of the interpolation (relative to the largest magnitude); never below 0 when
    /// the values are not (a density's majorant and minorant).
    Interval range(const Interval& x, const Interval& y, const Interval& z) const override;
    /// The largest difference of neighbouring samples along one axis over the spacing (a bound
    /// on the interpolant's partial derivatives), rounded up.
    double lipschitz() const override { return mLipschitz; }

    const BrickGrid<float>& grid() const { return mGrid; }
    Vec3 origin() const { return mOrigin; }
    double spacing() const { return mSpacing; }
    /// The box covered by the samples (it holds the baked box).
    Bounds3 sampledBounds() const;

private:
    Vec3 toIndex(const Vec3& p) const { return (p - mOrigin) * mInvSpacing; }

    BrickGrid<float> mGrid;
    Vec3 mOrigin;
    double mSpacing, mInvSpacing;
    double mLipschitz = 0.0;
};

/// Samples f on a grid over the box: `resolution` samples along its longest side (the box's
/// ends included), the same spacing on the others (rounded up to whole steps from box.lo, at
/// least 2 samples), stored as float. f is called in parallel (it must be thread safe) and
/// only inside the sampled box (sampledBounds(), at most one spacing past box.hi); the result
/// does not depend on the thread count.
/// Throws std::invalid_argument for a box that is not finite or has no extent, a resolution
/// outside [2, 4096], or a value of f that is not finite (naming the point).
std::shared_ptr<const BrickedField> bakeField(std::function<double(const Vec3&)> f,
                                              const Bounds3& box, int resolution);

}  // namespace kerf
