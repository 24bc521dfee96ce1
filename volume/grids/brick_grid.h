/// @file volume/grids/brick_grid.h
/// @brief A sparse two-level bricked 3-D array of T (Shirley et al., Fundamentals of Computer
/// Graphics §12.5), addressed by volume/grids/brick_index.h, for dense sampled fields (mist
/// density, caches of sampled implicits). Neighbours in every direction share cache lines and
/// pages, which a flat x-fastest array gives only along x.
///
/// - Sparse per macrobrick: one is allocated when first written. Unallocated ones point at a
///   shared block of background values, so reads never branch on allocation.
/// - Trilinear sampling in index space (voxel (i, j, k) at the point (i, j, k)): when the 2×2×2
///   stencil lies in one brick (7 cells in 8 per axis for n = 8) its corners are read at fixed
///   offsets from one key; otherwise the 8 keys are summed from the tables.
/// - Per-brick and per-macrobrick min/max bound the values of any voxel box (rangeOfVoxels).
///
/// T is an arithmetic type (float, double, an integer type). Reads are thread safe; writes are
/// not (set() may allocate). fill() writes the whole grid in parallel, deterministically.
#pragma once

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

#include "volume/grids/brick_index.h"

namespace kerf {

/// a + t·(b − a): the one interpolation formula of every trilinear sample here, so that the
/// bricked grid and a flat reference give the same bits.
inline double lerp1(double a, double b, double t) { return a + t * (b - a); }

/// Trilinear interpolation of corners c[dx + 2·dy + 4·dz]: along x first, then y, then z.
inline double trilinear(const double c[8], double tx, double ty, double tz) {
    const double c00 = lerp1(c[0], c[1], tx), c10 = lerp1(c[2], c[3], tx);
    const double c01 = lerp1(c[4], c[5], tx), c11 = lerp1(c[6], c[7], tx);
    return lerp1(lerp1(c00, c10, ty), lerp1(c01, c11, ty), tz);
}

/// The value (the same bits as trilinear()) and its partial derivatives in tx, ty, tz.
inline double trilinearGradient(const double c[8], double tx, double ty, double tz, double d[3]) {
    const double c00 = lerp1(c[0], c[1], tx), c10 = lerp1(c[2], c[3], tx);
    const double c01 = lerp1(c[4], c[5], tx), c11 = lerp1(c[6], c[7], tx);
    const double c0 = lerp1(c00, c10, ty), c1 = lerp1(c01, c11, ty);
    d[0] = lerp1(lerp1(c[1] - c[0], c[3] - c[2], ty), lerp1(c[5] - c[4], c[7] - c[6], ty), tz);
    d[1] = lerp1(c10 - c00, c11 - c01, tz);
    d[2] = c1 - c0;
    return lerp1(c0, c1, tz);
}

/// Where a trilinear sample at index-space u falls along one axis of s voxels: the cell's
/// lower voxel i, the upper one i1 (= i + 1 but for s = 1), the weight t, and whether u was
/// inside [0, s − 1] (outside, the value is extended constant from the edge).
struct SampleCell {
    int i, i1;
    double t;
    bool inside;
};

inline SampleCell sampleCell(double u, int s) {
    const double top = double(s - 1);
    const bool inside = u >= 0.0 && u <= top;
    const double c = u > 0.0 ? (u < top ? u : top) : 0.0;  // NaN goes to 0
    const int i = std::min(int(c), std::max(s - 2, 0));
    return {i, std::min(i + 1, s - 1), c - double(i), inside};
}

template <class T>
class BrickGrid {
    static_assert(std::is_arithmetic<T>::value, "BrickGrid holds numbers");

public:
    BrickGrid(glm::ivec3 size, T background, BrickLayout layout = {})
        : mIndex(size, layout),
          mBackground(background),
          mBackgroundBlock(new T[mIndex.macroVoxels()]),
          mMacros(mIndex.macroTotal()),
          mRead(mIndex.macroTotal()),
          mBrickMin(mIndex.brickTotal(), background),
          mBrickMax(mIndex.brickTotal(), background),
          mMacroMin(mIndex.macroTotal(), background),
          mMacroMax(mIndex.macroTotal(), background) {
        std::fill_n(mBackgroundBlock.get(), mIndex.macroVoxels(), background);
        std::fill(mRead.begin(), mRead.end(), mBackgroundBlock.get());
        const int n = mIndex.brickSide();
        mStride[0] = 1;
        mStride[1] = n;
        mStride[2] = n * n;
        mMask = n - 1;
    }

    const BrickIndex& index() const { return mIndex; }
    glm::ivec3 size() const { return mIndex.size(); }
    T background() const { return mBackground; }

    /// Voxel (x, y, z), inside size() (not checked).
    T get(int x, int y, int z) const {
        const std::uint64_t k = mIndex.key(x, y, z);
        return mRead[BrickIndex::macroOf(k)][BrickIndex::offsetOf(k)];
    }

    /// Writes voxel (x, y, z), allocating its macrobrick if needed; widens its brick's and
    /// macrobrick's min/max (an overwritten value may leave them wider than the data: still a
    /// bound; refreshRanges() makes them exact).
    void set(int x, int y, int z, T v) {
        const std::uint64_t k = mIndex.key(x, y, z);
        T* block = writable(BrickIndex::macroOf(k));
        block[BrickIndex::offsetOf(k)] = v;
        const int bn = mIndex.layout().brickLog2;
        const std::size_t b = mIndex.brickNumber(x >> bn, y >> bn, z >> bn);
        mBrickMin[b] = std::min(mBrickMin[b], v);
        mBrickMax[b] = std::max(mBrickMax[b], v);
        const std::size_t m = BrickIndex::macroOf(k);
        mMacroMin[m] = std::min(mMacroMin[m], v);
        mMacroMax[m] = std::max(mMacroMax[m], v);
    }

    /// Sets every voxel to f(x, y, z) (called in parallel: f must be thread safe), then frees
    /// the macrobricks that hold only the background value and makes the min/max exact. The
    /// result does not depend on the thread count.
    template <class F>
    void fill(F&& f) {
        const BrickIndex& ix = mIndex;
        const glm::ivec3 mc = ix.macroCount(), s = ix.size();
        const int side = ix.macroSide();
        tbb::parallel_for(std::size_t(0), ix.macroTotal(), [&](std::size_t m) {
            const int mx = int(m % mc.x), my = int(m / mc.x % mc.y),
                      mz = int(m / (std::size_t(mc.x) * mc.y));
            T* block = writable(std::uint32_t(m));
            bool any = false;
            for (int z = mz * side; z < std::min(s.z, (mz + 1) * side); ++z)
                for (int y = my * side; y < std::min(s.y, (my + 1) * side); ++y)
                    for (int x = mx * side; x < std::min(s.x, (mx + 1) * side); ++x) {
                        const T v = f(x, y, z);
                        block[BrickIndex::offsetOf(ix.key(x, y, z))] = v;
                        any = any || !(v == mBackground);
                    }
            if (!any) release(std::uint32_t(m));
        });
        refreshRanges();
    }

    /// Recomputes every brick's and macrobrick's min/max from the voxels (in parallel).
    void refreshRanges() {
        const glm::ivec3 bc = mIndex.brickCount(), s = mIndex.size();
        const int n = mIndex.brickSide();
        tbb::parallel_for(0, bc.z, [&](int bz) {
            for (int by = 0; by < bc.y; ++by)
                for (int bx = 0; bx < bc.x; ++bx) {
                    T lo = get(bx * n, by * n, bz * n), hi = lo;
                    for (int z = bz * n; z < std::min(s.z, (bz + 1) * n); ++z)
                        for (int y = by * n; y < std::min(s.y, (by + 1) * n); ++y)
                            for (int x = bx * n; x < std::min(s.x, (bx + 1) * n); ++x) {
                                const T v = get(x, y, z);
                                lo = std::min(lo, v);
                                hi = std::max(hi, v);
                            }
                    const std::size_t b = mIndex.brickNumber(bx, by, bz);
                    mBrickMin[b] = lo;
                    mBrickMax[b] = hi;
                }
        });
        // Each macrobrick from its own bricks (not brickRange, which reads the macro bounds).
        const glm::ivec3 mc = mIndex.macroCount();
        const int m = 1 << mIndex.layout().macroLog2;
        for (int mz = 0; mz < mc.z; ++mz)
            for (int my = 0; my < mc.y; ++my)
                for (int mx = 0; mx < mc.x; ++mx) {
                    const std::size_t k = mIndex.macroNumber(mx, my, mz);
                    const std::size_t b0 = mIndex.brickNumber(mx * m, my * m, mz * m);
                    T lo = mBrickMin[b0], hi = mBrickMax[b0];
                    for (int z = mz * m; z < std::min(bc.z, (mz + 1) * m); ++z)
                        for (int y = my * m; y < std::min(bc.y, (my + 1) * m); ++y)
                            for (int x = mx * m; x < std::min(bc.x, (mx + 1) * m); ++x) {
                                const std::size_t b = mIndex.brickNumber(x, y, z);
                                lo = std::min(lo, mBrickMin[b]);
                                hi = std::max(hi, mBrickMax[b]);
                            }
                    mMacroMin[k] = lo;
                    mMacroMax[k] = hi;
                }
    }

    /// Bounds (lo ≤ every voxel ≤ hi) of the voxels of the box [lo, hi] (inclusive, clamped to
    /// the grid): exact for a box of at most n³ voxels, otherwise from the per-brick and
    /// per-macrobrick min/max (then it may be wider: it covers the whole bricks the box meets).
    std::pair<T, T> rangeOfVoxels(glm::ivec3 lo, glm::ivec3 hi) const {
        const glm::ivec3 s = mIndex.size();
        lo = glm::clamp(lo, glm::ivec3(0), s - 1);
        hi = glm::clamp(hi, glm::ivec3(0), s - 1);
        // A box of at most one brick's worth of voxels is read directly (exact, and no dearer
        // than the bricks it may straddle); larger ones from the brick bounds.
        const glm::ivec3 e = glm::max(hi - lo + 1, glm::ivec3(0));
        const int bn = mIndex.layout().brickLog2;
        if (std::int64_t(e.x) * e.y * e.z <= (std::int64_t(1) << 3 * bn)) {
            T a = get(lo.x, lo.y, lo.z), b = a;
            for (int z = lo.z; z <= hi.z; ++z)
                for (int y = lo.y; y <= hi.y; ++y)
                    for (int x = lo.x; x <= hi.x; ++x) {
                        const T v = get(x, y, z);
                        a = std::min(a, v);
                        b = std::max(b, v);
                    }
            return {a, b};
        }
        return brickRange(lo >> bn, hi >> bn);
    }

    /// Trilinear sample at index-space (x, y, z), constant beyond the edges.
    double sample(double x, double y, double z) const {
        double c[8], t[3];
        gather(x, y, z, c, t);
        return trilinear(c, t[0], t[1], t[2]);
    }

    /// The sample (the same bits as sample()) and its gradient in index space (0 along an axis
    /// where the point is beyond the edge; one-sided on cell faces: the cell of the floor).
    double sampleGradient(double x, double y, double z, double g[3]) const {
        double c[8], t[3];
        bool inside[3];
        gather(x, y, z, c, t, inside);
        const double v = trilinearGradient(c, t[0], t[1], t[2], g);
        for (int a = 0; a < 3; ++a)
            if (!inside[a]) g[a] = 0.0;
        return v;
    }

    /// The 8 corners c[dx + 2·dy + 4·dz] of the cell holding (x, y, z) and the weights.
    void gather(double x, double y, double z, double c[8], double t[3],
                bool inside[3] = nullptr) const {
        const glm::ivec3 s = mIndex.size();
        const SampleCell cx = sampleCell(x, s.x), cy = sampleCell(y, s.y), cz = sampleCell(z, s.z);
        t[0] = cx.t;
        t[1] = cy.t;
        t[2] = cz.t;
        if (inside) {
            inside[0] = cx.inside;
            inside[1] = cy.inside;
            inside[2] = cz.inside;
        }
        const std::uint64_t* fx = mIndex.table(0);
        const std::uint64_t* fy = mIndex.table(1);
        const std::uint64_t* fz = mIndex.table(2);
        // Fast path: the stencil in one brick (the lower corner not on a brick's last layer,
        // and a true upper neighbour on each axis).
        if (((cx.i & mMask) != mMask) & ((cy.i & mMask) != mMask) & ((cz.i & mMask) != mMask) &
            (cx.i1 != cx.i) & (cy.i1 != cy.i) & (cz.i1 != cz.i)) {
            const std::uint64_t k = fx[cx.i] + fy[cy.i] + fz[cz.i];
            const T* p = mRead[BrickIndex::macroOf(k)] + BrickIndex::offsetOf(k);
            const int sy = mStride[1], sz = mStride[2];
            c[0] = double(p[0]);
            c[1] = double(p[1]);
            c[2] = double(p[sy]);
            c[3] = double(p[sy + 1]);
            c[4] = double(p[sz]);
            c[5] = double(p[sz + 1]);
            c[6] = double(p[sz + sy]);
            c[7] = double(p[sz + sy + 1]);
            return;
        }
        const std::uint64_t kx[2] = {fx[cx.i], fx[cx.i1]}, ky[2] = {fy[cy.i], fy[cy.i1]},
                            kz[2] = {fz[cz.i], fz[cz.i1]};
        for (int j = 0; j < 8; ++j) {
            const std::uint64_t k = kx[j & 1] + ky[(j >> 1) & 1] + kz[j >> 2];
            c[j] = double(mRead[BrickIndex::macroOf(k)][BrickIndex::offsetOf(k)]);
        }
    }

    /// A hint that the brick holding voxel (x, y, z) (clamped to the grid) will be read soon:
    /// its cache lines are prefetched, so a ray marcher can have a whole brick in flight
    /// instead of missing line by line. Returns the brick's number, for the caller to skip
    /// repeated hints for the same brick.
    std::size_t prefetchBrick(int x, int y, int z) const {
        const glm::ivec3 s = mIndex.size();
        x = std::min(std::max(x, 0), s.x - 1) & ~mMask;
        y = std::min(std::max(y, 0), s.y - 1) & ~mMask;
        z = std::min(std::max(z, 0), s.z - 1) & ~mMask;
        const std::uint64_t k = mIndex.key(x, y, z);
        const char* p =
            reinterpret_cast<const char*>(mRead[BrickIndex::macroOf(k)] + BrickIndex::offsetOf(k));
        const std::size_t bytes = sizeof(T) << 3 * mIndex.layout().brickLog2;
        for (std::size_t b = 0; b < bytes; b += 64) __builtin_prefetch(p + b);
        const int bn = mIndex.layout().brickLog2;
        return mIndex.brickNumber(x >> bn, y >> bn, z >> bn);
    }

    /// Macrobricks allocated (written to and not all background).
    std::size_t allocatedMacrobricks() const {
        return std::size_t(std::count_if(mMacros.begin(), mMacros.end(),
                                         [](const std::unique_ptr<T[]>& b) { return bool(b); }));
    }
    bool macroAllocated(std::size_t macro) const { return bool(mMacros[macro]); }
    /// Bytes held by voxels (allocated macrobricks and the background block).
    std::size_t voxelBytes() const {
        return (allocatedMacrobricks() + 1) * mIndex.macroVoxels() * sizeof(T);
    }

private:
    T* writable(std::uint32_t macro) {
        if (!mMacros[macro]) {
            mMacros[macro].reset(new T[mIndex.macroVoxels()]);
            std::fill_n(mMacros[macro].get(), mIndex.macroVoxels(), mBackground);
            mRead[macro] = mMacros[macro].get();
        }
        return mMacros[macro].get();
    }

    void release(std::uint32_t macro) {
        mMacros[macro].reset();
        mRead[macro] = mBackgroundBlock.get();
    }

    /// min/max over the bricks [blo, bhi] (inclusive, in range): whole macrobricks inside the
    /// box by their own min/max, the rest brick by brick.
    std::pair<T, T> brickRange(glm::ivec3 blo, glm::ivec3 bhi) const {
        const glm::ivec3 bc = mIndex.brickCount();
        blo = glm::clamp(blo, glm::ivec3(0), bc - 1);
        bhi = glm::clamp(bhi, glm::ivec3(0), bc - 1);
        const int mn = mIndex.layout().macroLog2, m = 1 << mn;
        bool first = true;
        T lo = mBackground, hi = mBackground;
        auto take = [&](T a, T b) {
            lo = first ? a : std::min(lo, a);
            hi = first ? b : std::max(hi, b);
            first = false;
        };
        for (int mz = blo.z >> mn; mz <= bhi.z >> mn; ++mz)
            for (int my = blo.y >> mn; my <= bhi.y >> mn; ++my)
                for (int mx = blo.x >> mn; mx <= bhi.x >> mn; ++mx) {
                    const glm::ivec3 mlo(mx * m, my * m, mz * m);
                    const glm::ivec3 mhi = glm::min(mlo + (m - 1), bc - 1);
                    const glm::ivec3 a = glm::max(mlo, blo), b = glm::min(mhi, bhi);
                    if (a == mlo && b == mhi) {
                        const std::size_t k = mIndex.macroNumber(mx, my, mz);
                        take(mMacroMin[k], mMacroMax[k]);
                        continue;
                    }
                    for (int z = a.z; z <= b.z; ++z)
                        for (int y = a.y; y <= b.y; ++y)
                            for (int x = a.x; x <= b.x; ++x) {
                                const std::size_t k = mIndex.brickNumber(x, y, z);
                                take(mBrickMin[k], mBrickMax[k]);
                            }
                }
        return {lo, hi};
    }

    BrickIndex mIndex;
    T mBackground;
    std::unique_ptr<T[]> mBackgroundBlock;      // read by unallocated macrobricks
    std::vector<std::unique_ptr<T[]>> mMacros;  // owned blocks, null when unallocated
    std::vector<const T*> mRead;                // per macrobrick: its block or the background's
    std::vector<T> mBrickMin, mBrickMax, mMacroMin, mMacroMax;
    int mStride[3];
    int mMask;
};

}  // namespace kerf
