// Early split clipping of thin triangles' references (mesh/bvh_split.h).
#include "mesh/bvh_split.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace kerf {

namespace {

double halfArea(const Bounds3& b) {
    if (b.empty()) return 0.0;
    const Vec3 e = b.extent();
    return e.x * e.y + e.y * e.z + e.z * e.x;
}

// A convex polygon of at most 9 vertices (a triangle clipped by 6 planes).
struct Polygon {
    Vec3 v[12];
    int n = 0;
};

// Keeps the part of p with x[axis] ≤ s (keepBelow) or ≥ s. The crossing points are rounded;
// boxOf widens for that.
Polygon clip(const Polygon& p, int axis, double s, bool keepBelow) {
    Polygon out;
    for (int i = 0; i < p.n; ++i) {
        const Vec3& a = p.v[i];
        const Vec3& b = p.v[(i + 1) % p.n];
        const bool aIn = keepBelow ? a[axis] <= s : a[axis] >= s;
        const bool bIn = keepBelow ? b[axis] <= s : b[axis] >= s;
        if (aIn) out.v[out.n++] = a;
        if (aIn != bIn) {
            const double f = (s - a[axis]) / (b[axis] - a[axis]);
            Vec3 x = a + f * (b - a);
            x[axis] = s;  // on the plane exactly
            out.v[out.n++] = x;
        }
    }
    return out;
}

double area(const Polygon& p) {
    Vec3 sum(0.0);
    for (int i = 1; i + 1 < p.n; ++i) sum += glm::cross(p.v[i] - p.v[0], p.v[i + 1] - p.v[0]);
    return 0.5 * glm::length(sum);
}

// The polygon's box widened by a relative 2^-40 of the triangle's coordinates (far above the
// few ulps the crossing points may be off), then cut to the half it lies in.
Bounds3 boxOf(const Polygon& p, const Bounds3& half, const Vec3& magnitude) {
    Bounds3 b;
    for (int i = 0; i < p.n; ++i) b.extend(p.v[i]);
    if (b.empty()) return half;  // lost to rounding: keep the whole half
    const Vec3 margin = 0x1p-40 * magnitude;
    return Bounds3::overlap({b.lo - margin, b.hi + margin}, half);
}

struct Splitter {
    int maxDepth;
    double ratio;
    Vec3 magnitude;
    Polygon triangle;

    void split(const Bounds3& box, const Polygon& part, int depth, uint32_t index,
               std::vector<TriangleRef>& out) const {
        if (depth >= maxDepth || !(halfArea(box) > ratio * area(part))) {
            out.push_back({box, index});
            return;
        }
        const Vec3 e = box.extent();
        const int axis = e.x >= e.y ? (e.x >= e.z ? 0 : 2) : (e.y >= e.z ? 1 : 2);
        const double s = 0.5 * (box.lo[axis] + box.hi[axis]);
        Bounds3 lower = box, upper = box;
        lower.hi[axis] = s;
        upper.lo[axis] = s;
        const Polygon below = clip(part, axis, s, true), above = clip(part, axis, s, false);
        split(boxOf(below, lower, magnitude), below, depth + 1, index, out);
        split(boxOf(above, upper, magnitude), above, depth + 1, index, out);
    }
};

}  // namespace

std::vector<TriangleRef> triangleReferences(const TriangleMesh& mesh, int maxDepth, double ratio) {
    const size_t count = mesh.triangles.size();
    // Each triangle's references on their own, then joined in triangle order.
    std::vector<std::vector<TriangleRef>> pieces(count);
    std::vector<TriangleRef> refs(count);
    tbb::parallel_for(size_t(0), count, [&](size_t i) {
        Splitter s{maxDepth, ratio, Vec3(0.0), {}};
        Bounds3 box;
        for (int k = 0; k < 3; ++k) {
            const Vec3& p = mesh.positions[mesh.triangles[i][size_t(k)]];
            s.triangle.v[k] = p;
            box.extend(p);
            s.magnitude = glm::max(s.magnitude, glm::abs(p));
        }
        s.triangle.n = 3;
        refs[i] = {box, uint32_t(i)};
        if (maxDepth > 0 && halfArea(box) > ratio * area(s.triangle))
            s.split(box, s.triangle, 0, uint32_t(i), pieces[i]);
    });
    size_t total = 0;
    for (size_t i = 0; i < count; ++i) total += pieces[i].empty() ? 1 : pieces[i].size();
    // The build indexes references with 32 bits: past that, no splitting.
    if (total > size_t(UINT32_MAX)) return refs;
    std::vector<TriangleRef> out;
    out.reserve(total);
    for (size_t i = 0; i < count; ++i) {
        if (pieces[i].empty())
            out.push_back(refs[i]);
        else
            out.insert(out.end(), pieces[i].begin(), pieces[i].end());
    }
    return out;
}

}  // namespace kerf
