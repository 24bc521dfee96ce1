#include "volume/grids/bricked_field.h"

#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace kerf {

namespace {

/// The largest |v(i+1) − v(i)| along any axis over the whole grid (exact: max commutes).
double largestNeighbourDifference(const BrickGrid<float>& g) {
    const glm::ivec3 s = g.size();
    return tbb::parallel_reduce(
        tbb::blocked_range<int>(0, s.z), 0.0,
        [&](const tbb::blocked_range<int>& r, double m) {
            for (int z = r.begin(); z < r.end(); ++z)
                for (int y = 0; y < s.y; ++y)
                    for (int x = 0; x < s.x; ++x) {
                        const double v = g.get(x, y, z);
                        if (x + 1 < s.x) m = std::max(m, std::fabs(double(g.get(x + 1, y, z)) - v));
                        if (y + 1 < s.y) m = std::max(m, std::fabs(double(g.get(x, y + 1, z)) - v));
                        if (z + 1 < s.z) m = std::max(m, std::fabs(double(g.get(x, y, z + 1)) - v));
                    }
            return m;
        },
        [](double a, double b) { return std::max(a, b); });
}

/// The index range of cells a coordinate interval [lo, hi] (index space) reaches: the same
/// sampleCell() as a sample, and floor is monotone, so every sample in the interval uses a cell
/// in [first, last].
void cellsOf(double lo, double hi, int s, int& first, int& last) {
    first = sampleCell(lo, s).i;
    last = sampleCell(hi, s).i1;
}

}  // namespace

BrickedField::BrickedField(BrickGrid<float> grid, Vec3 origin, double spacing)
    : mGrid(std::move(grid)), mOrigin(origin), mSpacing(spacing), mInvSpacing(1.0 / spacing) {
    if (!(spacing > 0.0) || !std::isfinite(mInvSpacing))
        throw std::invalid_argument("bricked field: spacing must be positive and finite");
    // The difference of two floats in double may round; two steps up cover it and the division.
    mLipschitz = roundUp(roundUp(roundUp(largestNeighbourDifference(mGrid)) / spacing));
}

Bounds3 BrickedField::sampledBounds() const {
    return {mOrigin, mOrigin + mSpacing * Vec3(mGrid.size() - 1)};
}

double BrickedField::value(const Vec3& p) const {
    const Vec3 u = toIndex(p);
    if (std::isnan(u.x + u.y + u.z)) return std::numeric_limits<double>::quiet_NaN();
    return mGrid.sample(u.x, u.y, u.z);
}

double BrickedField::valueGradient(const Vec3& p, Vec3& gradient) const {
    const Vec3 u = toIndex(p);
    if (std::isnan(u.x + u.y + u.z)) {
        gradient = Vec3(std::numeric_limits<double>::quiet_NaN());
        return gradient.x;
    }
    double g[3];
    const double v = mGrid.sampleGradient(u.x, u.y, u.z, g);
    gradient = Vec3(g[0], g[1], g[2]) * mInvSpacing;
    return v;
}

long double BrickedField::valueExtended(const glm::tvec3<long double>& p) const {
    using L = long double;
    const glm::ivec3 s = mGrid.size();
    L t[3];
    int i[3], i1[3];
    for (int a = 0; a < 3; ++a) {
        const L u = (p[a] - L(mOrigin[a])) / L(mSpacing);
        if (std::isnan(u)) return std::numeric_limits<L>::quiet_NaN();
        const L c = std::clamp(u, L(0), L(s[a] - 1));
        i[a] = std::min(int(c), std::max(s[a] - 2, 0));
        i1[a] = std::min(i[a] + 1, s[a] - 1);
        t[a] = c - L(i[a]);
    }
    auto at = [&](int dx, int dy, int dz) {
        return L(mGrid.get(dx ? i1[0] : i[0], dy ? i1[1] : i[1], dz ? i1[2] : i[2]));
    };
    auto lerp = [](L a, L b, L w) { return a + w * (b - a); };
    const L c0 =
        lerp(lerp(at(0, 0, 0), at(1, 0, 0), t[0]), lerp(at(0, 1, 0), at(1, 1, 0), t[0]), t[1]);
    const L c1 =
        lerp(lerp(at(0, 0, 1), at(1, 0, 1), t[0]), lerp(at(0, 1, 1), at(1, 1, 1), t[0]), t[1]);
    return lerp(c0, c1, t[2]);
}

Interval BrickedField::range(const Interval& x, const Interval& y, const Interval& z) const {
    if (x.maybeNan || y.maybeNan || z.maybeNan) return Interval::entire();
    const Interval box[3] = {x, y, z};
    const glm::ivec3 s = mGrid.size();
    glm::ivec3 lo, hi;
    for (int a = 0; a < 3; ++a) {
        // The same rounded map to index space as value(): monotone, so it keeps the order.
        const double ulo = (box[a].lo - mOrigin[a]) * mInvSpacing;
        const double uhi = (box[a].hi - mOrigin[a]) * mInvSpacing;
        if (std::isnan(ulo) || std::isnan(uhi)) return Interval::entire();
        cellsOf(ulo, uhi, s[a], lo[a], hi[a]);
    }
    const std::pair<float, float> r = mGrid.rangeOfVoxels(lo, hi);
    const double vlo = r.first, vhi = r.second;
    // A lerp a + t·(b − a) of inputs of magnitude ≤ M lands within about 5·2⁻⁵³·M of their
    // hull (three roundings, |b − a| ≤ 2M); three nested levels, 15·2⁻⁵³·M: the margin is
    // 32·2⁻⁵³·M. With a, b ≥ 0, rounding is monotone and fl(b − a) ≥ −a, so no lerp goes
    // below 0 (and symmetrically none above 0 for values ≤ 0).
    const double m = std::max(std::fabs(vlo), std::fabs(vhi));
    const double margin = roundUp(m * 0x1p-48);
    double l = roundDown(vlo - margin), h = roundUp(vhi + margin);
    if (vlo >= 0.0) l = std::max(l, 0.0);
    if (vhi <= 0.0) h = std::min(h, 0.0);
    return {l, h};
}

std::shared_ptr<const BrickedField> bakeField(std::function<double(const Vec3&)> f,
                                              const Bounds3& box, int resolution) {
    if (!f) throw std::invalid_argument("bake: no function to sample");
    if (!box.finite() || box.empty())
        throw std::invalid_argument("bake: the box must be finite and not empty");
    const Vec3 e = box.extent();
    const double longest = std::max({e.x, e.y, e.z});
    if (!(longest > 0.0)) throw std::invalid_argument("bake: the box has no extent");
    if (resolution < 2 || resolution > 4096) {
        std::ostringstream m;
        m << "bake: resolution " << resolution << " is outside [2, 4096] samples";
        throw std::invalid_argument(m.str());
    }
    const double h = longest / double(resolution - 1);
    glm::ivec3 size;
    for (int a = 0; a < 3; ++a) {
        const double steps = std::ceil(e[a] / h);
        size[a] = std::max(2, int(std::min(steps, 4095.0)) + 1);
    }
    const Vec3 origin = box.lo;
    BrickGrid<float> grid(size, 0.0f);
    std::atomic<bool> bad{false};
    grid.fill([&](int x, int y, int z) {
        const double v = f(origin + h * Vec3(x, y, z));
        if (!std::isfinite(v) || std::fabs(v) > double(std::numeric_limits<float>::max())) {
            bad.store(true, std::memory_order_relaxed);
            return 0.0f;
        }
        return float(v);
    });
    if (bad) {
        // The first bad sample in x-fastest order, found again serially so the message is
        // the same whatever the thread count.
        for (int z = 0; z < size.z; ++z)
            for (int y = 0; y < size.y; ++y)
                for (int x = 0; x < size.x; ++x) {
                    const Vec3 p = origin + h * Vec3(x, y, z);
                    const double v = f(p);
                    if (!std::isfinite(v) ||
                        std::fabs(v) > double(std::numeric_limits<float>::max())) {
                        std::ostringstream m;
                        m.precision(17);
                        m << "bake: the function is " << v << " at (" << p.x << ", " << p.y << ", "
                          << p.z << "): every sample must be finite and within float range";
                        throw std::invalid_argument(m.str());
                    }
                }
    }
    return std::make_shared<const BrickedField>(std::move(grid), origin, h);
}

}  // namespace kerf
