// Section planes: the in-plane axes and the plane's part of a box.
#include "slice/plane.h"

#include <algorithm>
#include <cmath>

namespace kerf {

SlicePlane SlicePlane::axisAligned(int axis, double offset) {
    SlicePlane p;
    const Vec3 e[3] = {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
    // Cyclic order keeps U × V = N: (x, y) for z, (y, z) for x, (z, x) for y.
    p.normal = e[axis];
    p.u = e[(axis + 1) % 3];
    p.v = e[(axis + 2) % 3];
    p.w = offset;
    return p;
}

SlicePlane SlicePlane::throughPoint(const Vec3& point, const Vec3& normal) {
    SlicePlane p;
    p.origin = point;
    p.normal = glm::normalize(normal);
    int least = 0;
    for (int a = 1; a < 3; ++a)
        if (std::fabs(p.normal[a]) < std::fabs(p.normal[least])) least = a;
    Vec3 e(0.0);
    e[least] = 1.0;
    p.u = glm::normalize(glm::cross(e, p.normal));
    p.v = glm::cross(p.normal, p.u);
    p.w = 0.0;
    return p;
}

PlaneRect planeSectionOfBox(const SlicePlane& plane, const Bounds3& box) {
    PlaneRect r{INFINITY, INFINITY, -INFINITY, -INFINITY};
    if (box.empty()) return r;
    const Vec3 base = plane.origin + plane.w * plane.normal;
    Vec3 corner[8];
    double dist[8];
    for (int i = 0; i < 8; ++i) {
        corner[i] = Vec3(i & 1 ? box.hi.x : box.lo.x, i & 2 ? box.hi.y : box.lo.y,
                         i & 4 ? box.hi.z : box.lo.z);
        dist[i] = glm::dot(corner[i] - base, plane.normal);
    }
    auto add = [&](const Vec3& p) {
        const double pu = glm::dot(p - plane.origin, plane.u);
        const double pv = glm::dot(p - plane.origin, plane.v);
        r.minU = std::min(r.minU, pu);
        r.maxU = std::max(r.maxU, pu);
        r.minV = std::min(r.minV, pv);
        r.maxV = std::max(r.maxV, pv);
    };
    // Corners on the plane, and the points where the 12 edges cross it.
    for (int i = 0; i < 8; ++i) {
        if (dist[i] == 0.0) add(corner[i]);
        for (int bit = 1; bit < 8; bit <<= 1) {
            const int j = i | bit;
            if (j == i) continue;
            if ((dist[i] < 0.0 && dist[j] > 0.0) || (dist[i] > 0.0 && dist[j] < 0.0)) {
                const double t = dist[i] / (dist[i] - dist[j]);
                add(corner[i] + t * (corner[j] - corner[i]));
            }
        }
    }
    return r;
}

}  // namespace kerf
