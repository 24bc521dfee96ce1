// A mesh's shape: validation and BVH at load, and its signed distance as a field. The sign
// comes from the parity of a ray's crossings, which the watertight test counts exactly; the
// magnitude from the BVH's nearest-triangle walk.
#include "mesh/mesh_shape.h"

#include "mesh/mesh_loader.h"
#include "mesh/triangle_distance.h"
#include "mesh/watertight_triangle.h"

#include <cmath>
#include <vector>

namespace kerf {

namespace {

double maxAbs(const Vec3& v) { return std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)}); }

/// A direction for the inside test with no simple ratio between its components (any direction
/// counts exactly; this one only makes rays along the mesh's own axes and faces unlikely).
const Vec3 kInsideDirection{0.5773502691896258, 0.6123724356957945, 0.5400617248673217};

}  // namespace

MeshShape::MeshShape(TriangleMesh mesh)
    : mMesh(std::move(mesh)), mBvh(mMesh), mReport(validateMesh(mMesh)) {}

Vec3 MeshShape::faceNormal(uint32_t triangle) const {
    const auto& t = mMesh.triangles[triangle];
    const Vec3& p0 = mMesh.positions[t[0]];
    return glm::cross(mMesh.positions[t[1]] - p0, mMesh.positions[t[2]] - p0);
}

Vec3 MeshShape::shadingNormal(uint32_t triangle, const Vec3& p, bool smooth) const {
    const Vec3 face = faceNormal(triangle);
    const double faceLength = glm::length(face);
    const Vec3 unitFace = faceLength > 0.0 ? face / faceLength : Vec3(0.0);
    if (!smooth || mMesh.normals.empty() || !(faceLength > 0.0)) return unitFace;
    // Barycentric weights of p (on the triangle) from the sub-triangles' areas along the face
    // normal.
    const auto& t = mMesh.triangles[triangle];
    const Vec3 &a = mMesh.positions[t[0]], &b = mMesh.positions[t[1]], &c = mMesh.positions[t[2]];
    const double f2 = faceLength * faceLength;
    const double w1 = glm::dot(glm::cross(p - a, c - a), face) / f2;  // weight of b
    const double w2 = glm::dot(glm::cross(b - a, p - a), face) / f2;  // weight of c
    const double w0 = 1.0 - w1 - w2;
    Vec3 n = w0 * mMesh.normals[t[0]] + w1 * mMesh.normals[t[1]] + w2 * mMesh.normals[t[2]];
    const double len = glm::length(n);
    if (!(len > 0.0) || !std::isfinite(len)) return unitFace;
    n /= len;
    // A vertex normal may lean past the face; shade on the face's side.
    return glm::dot(n, face) >= 0.0 ? n : unitFace;
}

bool MeshShape::inside(const Vec3& p) const {
    if (!isSolid()) return false;
    thread_local std::vector<TriangleCrossing> crossings;
    BvhStats stats;
    mBvh.allCrossings(Ray{p, kInsideDirection}, 0.0, kInf, crossings, stats);
    return crossings.size() % 2 == 1;
}

double MeshShape::distance(const Vec3& p) const {
    double d = kInf;
    uint32_t triangle = 0;
    BvhStats stats;
    mBvh.nearestTriangle(p, kInf, d, triangle, stats);
    return d;
}

double MeshShape::value(const Vec3& p) const {
    const double d = distance(p);
    return inside(p) ? -d : d;
}

long double MeshShape::valueExtended(const glm::tvec3<long double>& p) const {
    // The distance is the nearest point's, exact up to rounding in double; the reference
    // accuracy is measured against is the same zero set (the triangles themselves).
    return static_cast<long double>(value(Vec3(p)));
}

double MeshShape::valueGradient(const Vec3& p, Vec3& gradient) const {
    double d = kInf;
    uint32_t triangle = 0;
    BvhStats stats;
    if (!mBvh.nearestTriangle(p, kInf, d, triangle, stats)) {
        gradient = Vec3(0.0);
        return kInf;
    }
    const double sign = inside(p) ? -1.0 : 1.0;
    const auto& t = mMesh.triangles[triangle];
    const Vec3 q = nearestPointOnTriangle(p, mMesh.positions[t[0]], mMesh.positions[t[1]],
                                          mMesh.positions[t[2]]);
    const Vec3 away = p - q;
    const double len = glm::length(away);
    if (len > 0.0) {
        gradient = sign * away / len;
    } else {  // on the surface: the face's outward normal
        const Vec3 n = faceNormal(triangle);
        const double nl = glm::length(n);
        gradient = nl > 0.0 ? n / nl : Vec3(0.0);
    }
    return sign * d;
}

Interval MeshShape::range(const Interval& x, const Interval& y, const Interval& z) const {
    const Interval axes[3] = {x, y, z};
    Vec3 center, half;
    for (int a = 0; a < 3; ++a) {
        if (!std::isfinite(axes[a].lo) || !std::isfinite(axes[a].hi) || axes[a].maybeNan)
            return Interval(-kInf, kInf);
        center[a] = axes[a].mid();
        half[a] = std::max(axes[a].hi - center[a], center[a] - axes[a].lo);
    }
    const double d = distance(center);
    if (!std::isfinite(d)) return Interval(-kInf, kInf);
    // Every point of the box lies within r of the centre, and the distance changes by at most
    // what the point moves (it is 1-Lipschitz). `err` covers rounding in r and in d: each is
    // a few operations on coordinates no larger than `scale`, so 2^-40·scale is generous.
    const double r = glm::length(half) * (1.0 + 0x1p-50);
    const double scale =
        maxAbs(center) + maxAbs(half) + maxAbs(mBvh.bounds().lo) + maxAbs(mBvh.bounds().hi);
    const double err = 0x1p-40 * scale;
    const double hi = d + r + err;
    const double lo = d - r - err;
    if (lo > 0.0) {  // no surface in the box: one sign throughout
        if (inside(center)) return Interval(-hi, -lo);
        return Interval(lo, hi);
    }
    return isSolid() ? Interval(-hi, hi) : Interval(0.0, hi);
}

std::shared_ptr<const MeshShape> loadMeshShape(const std::string& path) {
    return std::make_shared<const MeshShape>(loadMesh(path));
}

}  // namespace kerf
