// polyhedron(points, faces) as a closed mesh solid. OpenSCAD lists each face's vertices
// clockwise seen from outside; kerf's triangles are counter-clockwise (mesh/mesh_shape.h), so
// faces are reversed, and the signed volume checks the result (a file written the other way
// round is taken as it is). Convex faces are split into fans; a face that is not convex is
// cut into ears (a fan of it could fold over itself) in the plane it is most nearly parallel
// to, and one that has no ear (it crosses itself) is an error naming it.
#include "lang/no_assets.h"
#include "lang/openscad_lower.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace kerf {

namespace {

/// The points as vectors of three finite numbers, or false.
bool readPoints(const ScadValue& v, std::vector<Vec3>& out) {
    if (v.kind != ScadValue::Kind::Vector) return false;
    for (const ScadValue& p : v.items) {
        if (p.kind != ScadValue::Kind::Vector || p.items.size() != 3) return false;
        for (const ScadValue& x : p.items)
            if (x.kind != ScadValue::Kind::Number || !std::isfinite(x.number)) return false;
        out.emplace_back(p.items[0].number, p.items[1].number, p.items[2].number);
    }
    return true;
}

/// The polygon's Newell normal: its direction is the side the polygon turns counter-clockwise
/// about, its length twice the area (of a planar polygon).
Vec3 newellNormal(const std::vector<Vec3>& poly) {
    Vec3 normal(0.0);
    const size_t n = poly.size();
    for (size_t i = 0; i < n; ++i) {
        const Vec3& a = poly[i];
        const Vec3& b = poly[(i + 1) % n];
        normal +=
            Vec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
    }
    return normal;
}

/// Whether the polygon turns one way only about its normal: then a fan from its first vertex
/// covers it exactly.
bool isConvex(const std::vector<Vec3>& poly, const Vec3& normal) {
    if (glm::dot(normal, normal) == 0) return false;  // no area: let earClip refuse it
    const size_t n = poly.size();
    for (size_t i = 0; i < n; ++i) {
        const Vec3 e0 = poly[(i + 1) % n] - poly[i];
        const Vec3 e1 = poly[(i + 2) % n] - poly[(i + 1) % n];
        if (glm::dot(glm::cross(e0, e1), normal) < 0) return false;
    }
    return true;
}

/// Ear clipping of a simple polygon (positions `poly`, mesh indices `idx`), seen in the
/// coordinate plane its normal is nearest to, oriented so it runs counter-clockwise there.
/// Appends the triangles in the polygon's own orientation; false if some step finds no ear
/// (the polygon crosses itself or is not planar enough to be seen as simple).
bool earClip(const std::vector<Vec3>& poly, const std::vector<uint32_t>& idx, const Vec3& normal,
             std::vector<std::array<uint32_t, 3>>& out) {
    int drop = 0;
    for (int a = 1; a < 3; ++a)
        if (std::abs(normal[a]) > std::abs(normal[drop])) drop = a;
    const int u = (drop + 1) % 3, v = (drop + 2) % 3;  // (u, v, drop) is right-handed
    const double sign = normal[drop] < 0 ? -1.0 : 1.0;
    std::vector<glm::dvec2> p;
    for (const Vec3& q : poly) p.emplace_back(q[u], sign * q[v]);
    auto cross = [&](size_t a, size_t b, size_t c) {
        return (p[b].x - p[a].x) * (p[c].y - p[a].y) - (p[b].y - p[a].y) * (p[c].x - p[a].x);
    };
    std::vector<size_t> ring(poly.size());
    for (size_t i = 0; i < ring.size(); ++i) ring[i] = i;
    while (ring.size() > 3) {
        bool clipped = false;
        for (size_t k = 0; k < ring.size() && !clipped; ++k) {
            const size_t a = ring[(k + ring.size() - 1) % ring.size()], b = ring[k],
                         c = ring[(k + 1) % ring.size()];
            if (cross(a, b, c) <= 0) continue;  // a reflex or flat corner is no ear
            bool empty = true;
            for (size_t j : ring) {
                if (j == a || j == b || j == c) continue;
                if (cross(a, b, j) >= 0 && cross(b, c, j) >= 0 && cross(c, a, j) >= 0) {
                    empty = false;
                    break;
                }
            }
            if (!empty) continue;
            out.push_back({idx[a], idx[b], idx[c]});
            ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(k));
            clipped = true;
        }
        if (!clipped) return false;
    }
    out.push_back({idx[ring[0]], idx[ring[1]], idx[ring[2]]});
    return true;
}

/// The point indices of one face into `idx`, or what is wrong with it ("has 2 indices, …")
/// with `where` moved to the index at fault.
std::string faceIndices(const ScadValue& face, size_t points, std::vector<uint32_t>& idx,
                        SourcePos& where) {
    const std::string range = "the points are 0 to " + std::to_string(points) + " − 1";
    if (face.kind != ScadValue::Kind::Vector) return "is not a vector of point indices";
    if (face.items.size() < 3)
        return "has " + std::to_string(face.items.size()) + " indices: a face needs at least three";
    for (size_t i = 0; i < face.items.size(); ++i) {
        const ScadValue& item = face.items[i];
        const double x = item.number;
        where = item.pos;
        if (item.kind != ScadValue::Kind::Number || !(x == std::floor(x)))
            return "index " + std::to_string(i) + " is not a whole number";
        if (!(x >= 0 && x < static_cast<double>(points)))
            return "index " + std::to_string(i) + " (" + formatNumber(x) +
                   ") is out of range: " + range;
        idx.push_back(static_cast<uint32_t>(x));
    }
    where = face.pos;
    return {};
}

}  // namespace

NodePtr lowerScadPolyhedron(const ScadCall& c, ScadLowering& lowering) {
    const ScadArg* pointsArg = c.arg("points", 0);
    const ScadArg* facesArg = c.arg("faces", 1);
    if (!facesArg) facesArg = c.arg("triangles");  // the name before OpenSCAD 2014.03
    if (!pointsArg || !facesArg) {
        lowering.error(c.pos, "polyhedron needs points and faces");
        return nullptr;
    }
    struct {
        std::vector<Vec3> positions;
        std::vector<std::array<uint32_t, 3>> triangles;
    } mesh;
    if (!readPoints(pointsArg->value, mesh.positions)) {
        lowering.error(pointsArg->value.pos,
                       "polyhedron points must be a vector of [x, y, z] finite numbers");
        return nullptr;
    }
    const ScadValue& faces = facesArg->value;
    if (faces.kind != ScadValue::Kind::Vector) {
        lowering.error(faces.pos, "polyhedron faces must be a vector of vectors of point indices");
        return nullptr;
    }
    for (size_t f = 0; f < faces.items.size(); ++f) {
        const ScadValue& face = faces.items[f];
        std::vector<uint32_t> idx;
        SourcePos where = face.pos;
        const std::string problem = faceIndices(face, mesh.positions.size(), idx, where);
        if (!problem.empty()) {
            lowering.error(where, "polyhedron face " + std::to_string(f) + " " + problem);
            return nullptr;
        }
        std::reverse(idx.begin(), idx.end());  // clockwise from outside → counter-clockwise
        std::vector<Vec3> poly;
        for (uint32_t i : idx) poly.push_back(mesh.positions[i]);
        const Vec3 normal = newellNormal(poly);
        if (isConvex(poly, normal)) {
            for (size_t i = 1; i + 1 < idx.size(); ++i)
                mesh.triangles.push_back({idx[0], idx[i], idx[i + 1]});
        } else if (!earClip(poly, idx, normal, mesh.triangles)) {
            lowering.error(face.pos, "polyhedron face " + std::to_string(f) + " crosses itself",
                           "a face must be a simple polygon; split it into simple ones");
            return nullptr;
        }
    }
    // Signed volume (divergence theorem, ×6): negative when the file's faces ran the other way.
    double volume = 0.0;
    for (const auto& t : mesh.triangles)
        volume +=
            glm::dot(mesh.positions[t[0]], glm::cross(mesh.positions[t[1]], mesh.positions[t[2]]));
    if (volume < 0)
        for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
    const SourceLoc loc = lowering.locate(c.pos);
    const std::string source = "polyhedron at " + *loc.file + ":" + std::to_string(loc.line);
    const std::shared_ptr<const MeshAsset> shape =
        lowering.assets().meshOf(std::move(mesh.positions), std::move(mesh.triangles), source);
    if (!shape) {
        lowering.error(c.pos, "polyhedron needs a mesh from the asset provider: " +
                                  std::string(NoAssets::kReason));
        return nullptr;
    }
    if (!shape->isSolid()) {
        const std::string why = shape->whyNotSolid();
        lowering.error(c.pos,
                       "polyhedron is not a closed solid: " +
                           (why.empty() ? std::string("it has no triangle") : why),
                       "every edge must be shared by exactly two faces that run it opposite ways");
        return nullptr;
    }
    return shape->leaf(false);
}

}  // namespace kerf
