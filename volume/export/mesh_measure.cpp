// Distances from a mesh to the implicit surface, and volumes.
#include "volume/export/mesh_measure.h"

#include "volume/export/mesh_placement.h"
#include "volume/octree/surface_search.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace kerf {

namespace {

/// Distance from q (model space) to the surface, and whether it is only first order.
double distanceToSurface(const SampledField& field, const Vec3& q, bool& firstOrder) {
    const MeshLattice& l = field.lattice;
    const Tape& tape = tapeNear(field, (q - l.origin) / l.voxel);
    return surfaceDistance(tape, q, 2.0 * l.voxel, 1e-9 * l.voxel, firstOrder);
}

}  // namespace

SurfaceDistance measureSurfaceDistance(const SampledField& field, const std::vector<Vec3>& vertices,
                                       const std::vector<std::array<uint32_t, 3>>& triangles) {
    // Per vertex, then per triangle (its centroid and the midpoints of the edges it owns: the
    // edge from a lower to a higher index, which a closed mesh's other triangle runs the other
    // way). The largest of independent per-item values: the same whatever the threads.
    std::vector<double> vd(vertices.size()), td(triangles.size()), tsum(triangles.size());
    std::vector<uint8_t> vf(vertices.size()), tf(triangles.size());
    tbb::parallel_for(size_t(0), vertices.size(), [&](size_t i) {
        bool first;
        vd[i] = distanceToSurface(field, vertices[i], first);
        vf[i] = first;
    });
    tbb::parallel_for(size_t(0), triangles.size(), [&](size_t i) {
        const auto& t = triangles[i];
        const Vec3 a = vertices[t[0]], b = vertices[t[1]], c = vertices[t[2]];
        bool first;
        double d = distanceToSurface(field, (a + b + c) / 3.0, first);
        double sum = d;
        uint8_t firsts = first;
        for (int e = 0; e < 3; ++e) {
            const uint32_t u = t[size_t(e)], w = t[size_t((e + 1) % 3)];
            if (u > w) continue;
            const double de = distanceToSurface(field, 0.5 * (vertices[u] + vertices[w]), first);
            d = std::max(d, de);
            sum += de;
            firsts += first;
        }
        td[i] = d;
        tf[i] = firsts;
        tsum[i] = sum;
    });
    SurfaceDistance out;
    double sum = 0.0;  // in a fixed order
    for (size_t i = 0; i < vd.size(); ++i) {
        out.hausdorff = std::max(out.hausdorff, vd[i]);
        out.firstOrder += vf[i];
        sum += vd[i];
    }
    for (size_t i = 0; i < td.size(); ++i) {
        out.hausdorff = std::max(out.hausdorff, td[i]);
        out.firstOrder += tf[i];
        sum += tsum[i];
    }
    out.samples = vertices.size() + triangles.size() + (3 * triangles.size()) / 2;
    out.mean = out.samples > 0 ? sum / double(out.samples) : 0.0;
    return out;
}

double enclosedVolume(const std::vector<Vec3>& vertices,
                      const std::vector<std::array<uint32_t, 3>>& triangles) {
    // About the first vertex, so a mesh far from the origin loses no digits.
    const Vec3 o = vertices.empty() ? Vec3(0.0) : vertices[0];
    double sum = 0.0;
    for (const auto& t : triangles)
        sum += glm::dot(vertices[t[0]] - o, glm::cross(vertices[t[1]] - o, vertices[t[2]] - o));
    return sum / 6.0;
}

VolumeBounds modelVolumeBounds(const SampledField& field) {
    const MeshLattice& l = field.lattice;
    const double h = l.voxel;
    std::vector<VolumeBounds> perBlock(field.boundary.size());
    tbb::parallel_for(size_t(0), field.boundary.size(), [&](size_t i) {
        const BoundaryBlock& b = field.boundary[i];
        double full = 0.0, maybe = 0.0;  // in half-voxel cells
        // The box of half-voxel cells [lo, lo + n/2] from half-voxel index s, its corners
        // computed as lattice points are.
        auto cellBox = [&](const int s[3], int n, Interval box[3]) {
            for (int a = 0; a < 3; ++a) {
                const double lo = double(int64_t(b.block[a]) * kMeshBlock) + 0.5 * s[a];
                box[a] = Interval(l.origin[a] + lo * h, l.origin[a] + (lo + 0.5 * n) * h);
            }
        };
        for (int x = 0; x < kMeshBlock; ++x)
            for (int y = 0; y < kMeshBlock; ++y)
                for (int z = 0; z < kMeshBlock; ++z) {
                    const int s[3] = {2 * x, 2 * y, 2 * z};
                    Interval box[3];
                    cellBox(s, 2, box);
                    const Classification c =
                        b.tape->evalInterval(box[0], box[1], box[2]).classify();
                    if (c == Classification::Filled) full += 8.0;
                    if (c != Classification::Ambiguous) continue;
                    for (int k = 0; k < 8; ++k) {  // the voxel's eight halves
                        const int t[3] = {s[0] + (k & 1), s[1] + ((k >> 1) & 1),
                                          s[2] + ((k >> 2) & 1)};
                        cellBox(t, 1, box);
                        const Classification ck =
                            b.tape->evalInterval(box[0], box[1], box[2]).classify();
                        if (ck == Classification::Filled) full += 1.0;
                        if (ck == Classification::Ambiguous) maybe += 1.0;
                    }
                }
        perBlock[i] = {full, full + maybe};
    });
    VolumeBounds out;
    const double cell = 0.125 * h * h * h;
    for (const VolumeBounds& v : perBlock) {
        out.lo += v.lo * cell;
        out.hi += v.hi * cell;
    }
    for (const FullRegion& r : field.full) {
        const double side = double(r.size) * kMeshBlock * h;
        out.lo += side * side * side;
        out.hi += side * side * side;
    }
    return out;
}

}  // namespace kerf
