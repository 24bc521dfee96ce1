// Proving a box's faces clear of a solid by interval subdivision.
#include "csg/primitives/clear_bound.h"

#include <cmath>

namespace kerf {
namespace {

/// f > 0 over the axis-aligned box [lo, hi] (one side may be flat), splitting it in two along
/// its widest side until proved or the budget is spent.
bool clearOver(const Tape& f, const Vec3& lo, const Vec3& hi, int& budget,
               std::vector<Choice>& choices) {
    if (--budget < 0) return false;
    // The recording evaluator keeps sums of squares non-negative, so a face through a
    // sphere's centre line does not get a possible NaN from sqrt of a rounded 0.
    const Interval v = f.evalInterval({lo.x, hi.x}, {lo.y, hi.y}, {lo.z, hi.z}, choices);
    if (!v.maybeNan && v.lo > 0.0) return true;
    if (!v.maybeNan && v.hi <= 0.0) return false;  // inside somewhere: not clear
    const Vec3 extent = hi - lo;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0
                     : extent.y >= extent.z                       ? 1
                                                                  : 2;
    const double mid = 0.5 * lo[axis] + 0.5 * hi[axis];
    if (!(mid > lo[axis] && mid < hi[axis])) return false;  // cannot split further
    Vec3 midHi = hi, midLo = lo;
    midHi[axis] = mid;
    midLo[axis] = mid;
    return clearOver(f, lo, midHi, budget, choices) && clearOver(f, midLo, hi, budget, choices);
}

}  // namespace

bool facesClear(const Tape& f, const Bounds3& box, int budget) {
    std::vector<Choice> choices;
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
            Vec3 lo = box.lo, hi = box.hi;
            const double at = side == 0 ? box.lo[axis] : box.hi[axis];
            lo[axis] = hi[axis] = at;
            if (!clearOver(f, lo, hi, budget, choices)) return false;
        }
    return true;
}

std::optional<Bounds3> grownClearBound(const Tape& f, const Bounds3& inner, double margin,
                                       int maxDoublings, int budgetPerTry) {
    if (inner.empty() || !inner.finite() || !(margin > 0.0) || !std::isfinite(margin))
        return std::nullopt;
    for (int k = 0; k <= maxDoublings; ++k, margin *= 2.0) {
        const Bounds3 box{inner.lo - Vec3(margin), inner.hi + Vec3(margin)};
        if (!box.finite()) return std::nullopt;
        if (facesClear(f, box, budgetPerTry)) return box;
    }
    return std::nullopt;
}

}  // namespace kerf
