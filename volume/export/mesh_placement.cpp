// Vertex placement on the true surface: dual contouring's quadric at creases, a bounded
// projection along the gradient elsewhere.
#include "volume/export/mesh_placement.h"

#include "volume/octree/surface_search.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace kerf {

namespace {

/// A quadric's eigenvalue below this fraction of the largest is dropped: two equal-weight
/// normals closer than about 35° (tan²(θ/2) = 0.1) count as one smooth surface.
constexpr double kRankThreshold = 0.1;
/// The largest first-order distance from the surface, in voxels, of an accepted crease point.
constexpr double kCreaseDistance = 0.1;

/// Eigen-decomposition of a symmetric 3×3 matrix by cyclic Jacobi rotations: a = v·diag(w)·vᵀ,
/// the eigenvectors in v's columns.
void symmetricEigen(double a[3][3], double w[3], double v[3][3]) {
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) v[i][j] = i == j ? 1.0 : 0.0;
    for (int sweep = 0; sweep < 32; ++sweep) {
        const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
        if (off == 0.0) break;
        for (int p = 0; p < 2; ++p)
            for (int q = p + 1; q < 3; ++q) {
                if (a[p][q] == 0.0) continue;
                const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
                const double t =
                    (theta >= 0 ? 1.0 : -1.0) / (std::fabs(theta) + std::sqrt(theta * theta + 1.0));
                const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
                for (int k = 0; k < 3; ++k) {  // a ← a·J
                    const double akp = a[k][p], akq = a[k][q];
                    a[k][p] = c * akp - s * akq;
                    a[k][q] = s * akp + c * akq;
                }
                for (int k = 0; k < 3; ++k) {  // a ← Jᵀ·a
                    const double apk = a[p][k], aqk = a[q][k];
                    a[p][k] = c * apk - s * aqk;
                    a[q][k] = s * apk + c * aqk;
                }
                for (int k = 0; k < 3; ++k) {
                    const double vkp = v[k][p], vkq = v[k][q];
                    v[k][p] = c * vkp - s * vkq;
                    v[k][q] = s * vkp + c * vkq;
                }
            }
    }
    for (int i = 0; i < 3; ++i) w[i] = a[i][i];
}

/// The crease point of the lattice cell with lowest corner `c`, or false where the cell's
/// crossings lie on one smooth piece of surface (or the minimum leaves the cell).
bool creasePoint(const Tape& tape, const MeshLattice& l, const std::array<int64_t, 3>& c,
                 Vec3& out) {
    Vec3 corner[8];
    double value[8];
    for (int k = 0; k < 8; ++k) {
        corner[k] = l.at(c[0] + (k & 1), c[1] + ((k >> 1) & 1), c[2] + ((k >> 2) & 1));
        value[k] = tape.eval(corner[k]);
    }
    double ata[3][3] = {}, atb[3] = {};
    Vec3 mass(0.0);
    int count = 0;
    for (int a = 0; a < 3; ++a)
        for (int k = 0; k < 8; ++k) {
            if (k & (1 << a)) continue;  // each edge once, from its lower end along axis a
            const int k2 = k | (1 << a);
            if ((value[k] <= 0.0) == (value[k2] <= 0.0)) continue;
            const Vec3 dir = corner[k2] - corner[k];
            const double t = refineCrossing(tape, corner[k], dir, 0.0, value[k], 1.0, value[k2],
                                            kPlacementRootTolerance);
            const Vec3 p = corner[k] + t * dir;
            Vec3 g;
            tape.evalGradient(p, g);
            const double len = glm::length(g);
            if (!(len > 0.0) || !std::isfinite(len)) return false;
            const Vec3 n = g / len;
            for (int i = 0; i < 3; ++i) {
                for (int j = 0; j < 3; ++j) ata[i][j] += n[i] * n[j];
                atb[i] += n[i] * glm::dot(n, p);
            }
            mass += p;
            ++count;
        }
    if (count < 2) return false;
    mass /= double(count);
    // Minimise Σ (n·(x − p))² about the mass point, in the eigenvectors whose eigenvalues
    // count (a truncated pseudo-inverse): along a crease the mass point's position is kept.
    double r[3];
    for (int i = 0; i < 3; ++i)
        r[i] = atb[i] - (ata[i][0] * mass.x + ata[i][1] * mass.y + ata[i][2] * mass.z);
    double w[3], v[3][3];
    symmetricEigen(ata, w, v);
    const double largest = std::max({w[0], w[1], w[2]});
    int rank = 0;
    Vec3 x = mass;
    for (int e = 0; e < 3; ++e) {
        if (!(w[e] >= kRankThreshold * largest)) continue;
        ++rank;
        const Vec3 u(v[0][e], v[1][e], v[2][e]);
        x += (glm::dot(u, Vec3(r[0], r[1], r[2])) / w[e]) * u;
    }
    if (rank < 2) return false;
    const Vec3 lo = corner[0] - 0.5 * l.voxel, hi = corner[7] + 0.5 * l.voxel;
    if (!(glm::all(glm::greaterThanEqual(x, lo)) && glm::all(glm::lessThanEqual(x, hi))))
        return false;
    // A crease point is on the surface (both sheets meet there); a minimum far from it means
    // the normals varied for another reason (a thin or tightly curved part of the surface).
    Vec3 g;
    const double fx = tape.evalGradient(x, g);
    if (!(std::fabs(fx) <= kCreaseDistance * l.voxel * glm::length(g))) return false;
    out = x;
    return true;
}

/// The crease point of a cell holding the vertex at `index` (lattice index space). OpenVDB
/// puts a vertex on its cell's face where the crossings lie at the cell's corners (a face of
/// the solid through lattice points), so every cell within 1e-6 voxel is tried, nearest first.
/// Several vertices of one cell may go to the same crease point: their polygons then have
/// no area, which keeps the mesh closed and its crease sharp.
bool creaseNear(const Tape& tape, const MeshLattice& l, const Vec3& index, Vec3& out) {
    constexpr double kFuzz = 1e-6;
    // Per axis, the floor cell first, then the neighbour whose face the vertex is on.
    int64_t choice[3][2];
    int count[3];
    for (int a = 0; a < 3; ++a) {
        const double c = std::floor(index[a]);
        choice[a][0] = int64_t(c);
        count[a] = 1;
        if (index[a] - c < kFuzz)
            choice[a][count[a]++] = int64_t(c) - 1;
        else if (c + 1.0 - index[a] < kFuzz)
            choice[a][count[a]++] = int64_t(c) + 1;
    }
    for (int i = 0; i < count[0]; ++i)
        for (int j = 0; j < count[1]; ++j)
            for (int k = 0; k < count[2]; ++k)
                if (creasePoint(tape, l, {choice[0][i], choice[1][j], choice[2][k]}, out))
                    return true;
    return false;
}

}  // namespace

void placeVertices(const SampledField& field, std::vector<Vec3>& points, PlacementStats& stats) {
    const MeshLattice& l = field.lattice;
    std::atomic<uint64_t> features{0}, projected{0}, kept{0};
    tbb::parallel_for(size_t(0), points.size(), [&](size_t i) {
        const Tape& tape = tapeNear(field, points[i]);
        const Vec3 p = modelFromIndex(l, points[i]);
        Vec3 placed;
        if (creaseNear(tape, l, points[i], placed)) {
            points[i] = placed;
            features.fetch_add(1, std::memory_order_relaxed);
        } else if (rootAlongGradient(tape, p, l.voxel, kPlacementRootTolerance * l.voxel, placed)) {
            points[i] = placed;
            projected.fetch_add(1, std::memory_order_relaxed);
        } else {
            points[i] = p;
            kept.fetch_add(1, std::memory_order_relaxed);
        }
    });
    stats.features = features;
    stats.projected = projected;
    stats.kept = kept;
}

void splitQuads(const SampledField& field, const std::vector<Vec3>& points,
                const std::vector<std::array<uint32_t, 4>>& quads,
                std::vector<std::array<uint32_t, 3>>& triangles) {
    const MeshLattice& l = field.lattice;
    std::vector<uint8_t> alternate(quads.size());
    tbb::parallel_for(size_t(0), quads.size(), [&](size_t i) {
        const auto& q = quads[i];
        double d[2];
        for (int k = 0; k < 2; ++k) {
            const Vec3 m = 0.5 * (points[q[size_t(k)]] + points[q[size_t(k + 2)]]);
            Vec3 g;
            const double f = tapeNear(field, (m - l.origin) / l.voxel).evalGradient(m, g);
            d[k] = std::fabs(f) / glm::length(g);
            if (!std::isfinite(d[k])) d[k] = HUGE_VAL;
        }
        alternate[i] = d[0] - d[1] > 1e-7 * l.voxel;
    });
    triangles.reserve(triangles.size() + 2 * quads.size());
    for (size_t i = 0; i < quads.size(); ++i) {
        const auto& q = quads[i];
        if (alternate[i]) {  // along the diagonal 1–3
            triangles.push_back({q[0], q[1], q[3]});
            triangles.push_back({q[1], q[2], q[3]});
        } else {  // along 0–2
            triangles.push_back({q[0], q[1], q[2]});
            triangles.push_back({q[0], q[2], q[3]});
        }
    }
}

}  // namespace kerf
