// The ray walk of a level set (volume/grids/level_set_grid.h): a DDA over groups; inside a group
// that can change sign, over its tiles of 4³ blocks; inside such a tile, over its blocks; inside
// such a block, over its cells. A stretch whose samples all have one sign is skipped (the
// interpolant is a convex combination of its corners there). In a cell whose corners have both
// signs the interpolant along the ray is a cubic in t; its critical points split the cell's
// segment into monotone pieces, so a sign change between a piece's ends is exactly one root
// (found by bracketed regula falsi), and no sign change means no crossing, except at a critical
// point where the cubic touches zero (a ray grazing the surface): a value there within the
// evaluation's rounding bound is a double root.
#include "volume/grids/level_set_grid.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace kerf {

/// One walk's state: the ray relative to the grid's first sample, whether the ray is inside,
/// and the crossings found so far.
class LevelSetWalker {
public:
    LevelSetWalker(const LevelSetGrid& grid, const Ray& ray, bool firstOnly,
                   std::vector<LevelSetCrossing>& out)
        : mGrid(grid), mFirstOnly(firstOnly), mOut(out) {
        for (int a = 0; a < 3; ++a) {
            mO[a] = ray.origin[a] - grid.mLo[a];
            mD[a] = ray.dir[a];
            mInv[a] = 1.0 / mD[a];  // ±inf for 0: never used, the axis never steps
        }
    }

    /// Whether the state is already known at the start (the ray starts outside the stored
    /// groups: the background, outside).
    void startOutside() { mKnown = true; }
    bool startInside() const { return mStartInside; }

    /// Walks [t0, t1] (inside the stored groups).
    void run(double t0, double t1) {
        const int lo[3] = {0, 0, 0};
        dda(double(kGroupCells), lo, mGrid.mGroups, t0, t1, [&](const int* g, double a, double b) {
            const LevelSetGrid::Group& group = mGrid.groupAt(g[0], g[1], g[2]);
            if (group.firstBlock < 0 || group.lo > 0.f || group.hi <= 0.f)
                return region(a, group.hi <= 0.f);
            // Tiles of 4³ blocks, then the blocks of a tile that can change sign.
            constexpr int n = kGroup / kTile;
            const std::pair<float, float>* tiles =
                &mGrid.mTiles[size_t(group.firstBlock) / (kGroup * kGroup * kGroup) * (n * n * n)];
            const int tlo[3] = {g[0] * n, g[1] * n, g[2] * n};
            const int thi[3] = {tlo[0] + n, tlo[1] + n, tlo[2] + n};
            return dda(
                double(kTile * kBlock), tlo, thi, a, b, [&](const int* tc, double ta, double tb) {
                    const auto& tile =
                        tiles[((tc[2] - tlo[2]) * n + (tc[1] - tlo[1])) * n + (tc[0] - tlo[0])];
                    if (tile.first > 0.f || tile.second <= 0.f)
                        return region(ta, tile.second <= 0.f);
                    const int blo[3] = {tc[0] * kTile, tc[1] * kTile, tc[2] * kTile};
                    const int bhi[3] = {blo[0] + kTile, blo[1] + kTile, blo[2] + kTile};
                    return dda(double(kBlock), blo, bhi, ta, tb,
                               [&](const int* c, double ba, double bb) {
                                   return block(group, c, ba, bb);
                               });
                });
        });
    }

private:
    static constexpr int kBlock = LevelSetGrid::kBlock;
    static constexpr int kGroup = LevelSetGrid::kGroup;
    static constexpr int kTile = LevelSetGrid::kTile;
    static constexpr int kGroupCells = kBlock * kGroup;
    static constexpr int kSide = kBlock + 1;

    /// Visits the cells of side `size` in [lo, hi) that the ray crosses over [t0, t1], in
    /// order, with each cell's own t-range; stops when `f` returns false.
    template <typename F>
    bool dda(double size, const int lo[3], const int hi[3], double t0, double t1, F&& f) const {
        int c[3], step[3];
        double next[3];
        const double inv = 1.0 / size;  // a power of two: exact
        for (int a = 0; a < 3; ++a) {
            const double p = (mO[a] + t0 * mD[a]) * inv;
            c[a] = std::clamp(p >= lo[a] ? int(std::floor(p)) : lo[a], lo[a], hi[a] - 1);
            step[a] = mD[a] > 0 ? 1 : (mD[a] < 0 ? -1 : 0);
            next[a] = boundary(a, c[a], step[a], size);
        }
        double t = t0;
        for (;;) {
            const int a =
                next[0] < next[1] ? (next[0] < next[2] ? 0 : 2) : (next[1] < next[2] ? 1 : 2);
            const double te = std::max(t, std::min(next[a], t1));
            if (!f(c, t, te)) return false;
            if (te >= t1) return true;
            c[a] += step[a];
            if (c[a] < lo[a] || c[a] >= hi[a]) return true;
            t = te;
            next[a] = boundary(a, c[a], step[a], size);
        }
    }

    /// Where the ray leaves cell c along axis a (inf when it never does). A multiply by the
    /// reciprocal, not a division: the walk only orders cells by these, and each cell's cubic
    /// is solved over the range they give, so a rounding here moves no crossing.
    double boundary(int a, int c, int step, double size) const {
        if (step == 0) return kInf;
        return ((step > 0 ? c + 1 : c) * size - mO[a]) * mInv[a];
    }

    bool block(const LevelSetGrid::Group& group, const int* b, double t0, double t1) {
        const int local = ((b[2] % kGroup) * kGroup + b[1] % kGroup) * kGroup + b[0] % kGroup;
        const LevelSetGrid::Block& blk = mGrid.mBlockList[group.firstBlock + local];
        if (blk.brick < 0 || blk.lo > 0.f || blk.hi <= 0.f) return region(t0, blk.hi <= 0.f);
        const float* brick = &mGrid.mBricks[size_t(blk.brick) * kSide * kSide * kSide];
        const int clo[3] = {b[0] * kBlock, b[1] * kBlock, b[2] * kBlock};
        const int chi[3] = {clo[0] + kBlock, clo[1] + kBlock, clo[2] + kBlock};
        return dda(1.0, clo, chi, t0, t1, [&](const int* c, double a, double e) {
            const float* s =
                brick + ((c[2] - clo[2]) * kSide + (c[1] - clo[1])) * kSide + (c[0] - clo[0]);
            const float corners[8] = {s[0],
                                      s[1],
                                      s[kSide],
                                      s[kSide + 1],
                                      s[kSide * kSide],
                                      s[kSide * kSide + 1],
                                      s[kSide * kSide + kSide],
                                      s[kSide * kSide + kSide + 1]};
            float mn = corners[0], mx = corners[0];
            for (int k = 1; k < 8; ++k) {
                mn = std::min(mn, corners[k]);
                mx = std::max(mx, corners[k]);
            }
            if (mn > 0.f || mx <= 0.f) return region(a, mx <= 0.f);
            return cell(corners, c, a, e);
        });
    }

    /// Entering a stretch that is all inside or all outside at t: a crossing at t if the
    /// state so far says otherwise (rounding where two cells meet).
    bool region(double t, bool inside) {
        if (!mKnown) {
            mKnown = true;
            mInside = mStartInside = inside;
            return true;
        }
        if (inside == mInside) return true;
        Vec3 g;
        const Vec3 p(mO[0] + t * mD[0] + mGrid.mLo[0], mO[1] + t * mD[1] + mGrid.mLo[1],
                     mO[2] + t * mD[2] + mGrid.mLo[2]);
        mGrid.valueGradient(p, g);
        return emit(t, inside, g);
    }

    bool emit(double t, bool entering, const Vec3& gradient) {
        mInside = entering;
        mOut.push_back({t, entering, gradient});
        return !mFirstOnly;
    }

    /// The cell c with corners cs over [t0, t1]: the cubic along the ray and its roots.
    bool cell(const float cs[8], const int* c, double t0, double t1) {
        const double u0 = mO[0] + t0 * mD[0] - c[0], v0 = mO[1] + t0 * mD[1] - c[1],
                     w0 = mO[2] + t0 * mD[2] - c[2];
        const double du = mD[0], dv = mD[1], dw = mD[2];
        // f = a0 + a1 u + a2 v + a3 w + a4 uv + a5 uw + a6 vw + a7 uvw.
        const double c0 = cs[0], c1 = cs[1], c2 = cs[2], c3 = cs[3], c4 = cs[4], c5 = cs[5],
                     c6 = cs[6], c7 = cs[7];
        const double a[8] = {c0,
                             c1 - c0,
                             c2 - c0,
                             c4 - c0,
                             c3 - c1 - c2 + c0,
                             c5 - c1 - c4 + c0,
                             c6 - c2 - c4 + c0,
                             c7 - c3 - c5 - c6 + c1 + c2 + c4 - c0};
        // The linear factors u = u0 + s·du, …, multiplied out in s = t − t0.
        const double uv[3] = {u0 * v0, u0 * dv + du * v0, du * dv};
        const double uw[3] = {u0 * w0, u0 * dw + du * w0, du * dw};
        const double vw[3] = {v0 * w0, v0 * dw + dv * w0, dv * dw};
        const double uvw[4] = {uv[0] * w0, uv[0] * dw + uv[1] * w0, uv[1] * dw + uv[2] * w0,
                               uv[2] * dw};
        const double k[4] = {a[0] + a[1] * u0 + a[2] * v0 + a[3] * w0 + a[4] * uv[0] +
                                 a[5] * uw[0] + a[6] * vw[0] + a[7] * uvw[0],
                             a[1] * du + a[2] * dv + a[3] * dw + a[4] * uv[1] + a[5] * uw[1] +
                                 a[6] * vw[1] + a[7] * uvw[1],
                             a[4] * uv[2] + a[5] * uw[2] + a[6] * vw[2] + a[7] * uvw[2],
                             a[7] * uvw[3]};
        const double len = t1 - t0;
        if (!region(t0, k[0] <= 0.0)) return false;
        if (!(len > 0.0)) return true;
        const auto f = [&](double s) { return ((k[3] * s + k[2]) * s + k[1]) * s + k[0]; };
        // The critical points inside (0, len): roots of 3k3 s² + 2k2 s + k1.
        double pts[4] = {0.0, 0.0, 0.0, 0.0};
        int n = 1;
        criticalPoints(3 * k[3], 2 * k[2], k[1], len, pts, n);
        pts[n++] = len;
        // Rounding bound of the cubic's value: its coefficients and Horner's steps each round
        // a few times over terms no larger than the corners' magnitude (|u|, |v|, |w| ≲ 1).
        double scale = 0.0;
        for (int i = 0; i < 8; ++i) scale = std::max(scale, std::fabs(double(cs[i])));
        const double tolerance = 64 * DBL_EPSILON * scale;
        double fa = k[0];
        for (int i = 0; i + 1 < n; ++i) {
            const double sa = pts[i], sb = pts[i + 1];
            const double fb = f(sb);
            if ((fa > 0.0) != (fb > 0.0)) {
                const double s = root(f, sa, sb, fa, fb);
                if (!emit(t0 + s, fb <= 0.0, gradient(a, u0 + s * du, v0 + s * dv, w0 + s * dw)))
                    return false;
            } else if (fb > 0.0 && fb <= tolerance && i + 2 < n && f(pts[i + 2]) > 0.0 &&
                       fa > 0.0) {
                // A touch from outside at an interior critical point: a double root.
                const Vec3 g = gradient(a, u0 + sb * du, v0 + sb * dv, w0 + sb * dw);
                if (!emit(t0 + sb, true, g) || !emit(t0 + sb, false, g)) return false;
            }
            fa = fb;
        }
        return true;
    }

    /// Appends to pts[n…] the roots of q2 s² + q1 s + q0 in (0, len), sorted.
    static void criticalPoints(double q2, double q1, double q0, double len, double* pts, int& n) {
        double r[2];
        int m = 0;
        if (q2 == 0.0) {
            if (q1 != 0.0) r[m++] = -q0 / q1;
        } else {
            const double disc = q1 * q1 - 4 * q2 * q0;
            if (disc >= 0.0) {
                const double q = -0.5 * (q1 + std::copysign(std::sqrt(disc), q1));
                r[m++] = q / q2;
                if (q != 0.0) r[m++] = q0 / q;
            }
        }
        if (m == 2 && r[0] > r[1]) std::swap(r[0], r[1]);
        for (int i = 0; i < m; ++i)
            if (r[i] > 0.0 && r[i] < len && (n == 1 || r[i] > pts[n - 1])) pts[n++] = r[i];
    }

    /// The root of a monotone piece with f(sa) and f(sb) on opposite sides of 0 (> 0 against
    /// ≤ 0): the first point of sb's side, to a few ulps, by Illinois regula falsi.
    template <typename F>
    static double root(const F& f, double sa, double sb, double fa, double fb) {
        const bool bSide = fb > 0.0;
        int side = 0;
        for (int it = 0; it < 100; ++it) {
            const double width = sb - sa;
            if (width <= 4 * DBL_EPSILON * std::max(std::fabs(sa), std::fabs(sb))) break;
            double s = sb - fb * (width / (fb - fa));
            if (!(s > sa && s < sb) || it % 8 == 7) s = sa + 0.5 * width;  // bisect as a guard
            if (s <= sa || s >= sb) break;
            const double fs = f(s);
            if ((fs > 0.0) == bSide) {
                sb = s, fb = fs;
                if (side == -1) fa *= 0.5;
                side = -1;
            } else {
                sa = s, fa = fs;
                if (side == 1) fb *= 0.5;
                side = 1;
            }
        }
        return sb;
    }

    static Vec3 gradient(const double a[8], double u, double v, double w) {
        return {a[1] + a[4] * v + a[5] * w + a[7] * v * w,
                a[2] + a[4] * u + a[6] * w + a[7] * u * w,
                a[3] + a[5] * u + a[6] * v + a[7] * u * v};
    }

    const LevelSetGrid& mGrid;
    bool mFirstOnly;
    std::vector<LevelSetCrossing>& mOut;
    double mO[3], mD[3], mInv[3];
    bool mKnown = false, mInside = false, mStartInside = false;
};

bool LevelSetGrid::walk(const Ray& ray, double tmin, double tmax, bool firstOnly,
                        std::vector<LevelSetCrossing>& out) const {
    out.clear();
    // Clip to the stored groups; beyond them is the background (outside).
    double t0 = tmin, t1 = tmax;
    for (int a = 0; a < 3; ++a) {
        const double o = ray.origin[a] - mLo[a], d = ray.dir[a];
        const double n = double(mGroups[a]) * kGroup * kBlock;
        if (d == 0.0) {
            if (!(o >= 0.0 && o <= n)) return false;
            continue;
        }
        double ta = (0.0 - o) / d, tb = (n - o) / d;
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
    }
    if (!(t0 < t1)) return tmin == t0 && std::isfinite(tmin) && value(ray.at(tmin)) <= 0.0;
    if (!std::isfinite(t0) || !std::isfinite(t1)) {  // a zero direction: no crossings
        return std::isfinite(tmin) ? value(ray.at(tmin)) <= 0.0 : false;
    }
    LevelSetWalker walker(*this, ray, firstOnly, out);
    if (t0 > tmin) walker.startOutside();
    walker.run(t0, t1);
    return walker.startInside();
}

}  // namespace kerf
