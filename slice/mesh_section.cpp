// Exact mesh sections: segments per crossed triangle, oriented by the triangle's winding,
// linked through the mesh edges they cut.
#include "slice/mesh_section.h"

#include "mesh/half_edges.h"
#include "mesh/mesh_shape.h"

#include <unordered_map>
#include <variant>

namespace kerf {

std::shared_ptr<const PlacedMesh> placedMeshOf(const Node& object) {
    Affine worldFromLocal;
    const Node* node = &object;
    for (;;) {
        const NodeKind kind = node->kind();
        if (kind == NodeKind::Material) {
            node = node->children()[0].get();
        } else if (kind == NodeKind::Transform) {
            const Affine m =
                std::get<TransformParams>(node->params()).worldFromLocal;  // params() is a copy
            worldFromLocal = worldFromLocal.after(m);
            node = node->children()[0].get();
        } else if (kind == NodeKind::Mesh) {
            break;
        } else {
            return nullptr;
        }
    }
    const std::shared_ptr<const MeshShape> held = std::get<MeshParams>(node->params()).shape;
    const MeshShape& shape = *held;
    auto placed = std::make_shared<PlacedMesh>();
    placed->solid = shape.isSolid();
    placed->triangles = shape.mesh().triangles;
    placed->weld = buildHalfEdges(shape.mesh()).weld;
    placed->positions.reserve(shape.mesh().positions.size());
    for (const Vec3& p : shape.mesh().positions)
        placed->positions.push_back(worldFromLocal.point(p));
    return placed;
}

std::vector<SectionLoop> meshSectionLoops(const PlacedMesh& mesh, const SlicePlane& plane) {
    const Vec3 n = glm::normalize(plane.normal);
    const Vec3 base = plane.at(0.0, 0.0);
    std::vector<double> height(mesh.positions.size());
    for (size_t i = 0; i < mesh.positions.size(); ++i)
        height[i] = glm::dot(mesh.positions[i] - base, n);
    auto below = [&](uint32_t v) { return height[v] < 0.0; };
    // Where the plane cuts the edge between two (welded) vertices: computed from the lower
    // index first, so the two triangles on the edge get the same bits.
    auto cut = [&](uint32_t a, uint32_t b) {
        if (mesh.weld[a] > mesh.weld[b]) std::swap(a, b);
        const double ha = height[a], hb = height[b];
        const Vec3 p =
            mesh.positions[a] + (ha / (ha - hb)) * (mesh.positions[b] - mesh.positions[a]);
        const Vec3 d = p - base;
        return std::array<double, 2>{glm::dot(d, plane.u), glm::dot(d, plane.v)};
    };
    auto key = [&](uint32_t a, uint32_t b) {
        uint64_t x = mesh.weld[a], y = mesh.weld[b];
        if (x > y) std::swap(x, y);
        return (x << 32) | y;
    };
    struct Segment {
        uint64_t from, to;  // the edges it starts and ends on
        std::array<double, 2> start;
    };
    std::vector<Segment> segments;
    std::unordered_map<uint64_t, size_t> startingAt;  // edge → the segment starting on it
    for (const auto& t : mesh.triangles) {
        int down = -1, up = -1;  // corners k whose edge k → k+1 goes above→below, below→above
        for (int k = 0; k < 3; ++k) {
            const bool b0 = below(t[k]), b1 = below(t[(k + 1) % 3]);
            if (!b0 && b1) down = k;
            if (b0 && !b1) up = k;
        }
        if (down < 0 || up < 0) continue;
        // Inside on the left: from the edge that goes down to the one that comes up.
        const uint32_t d0 = t[down], d1 = t[(down + 1) % 3], u0 = t[up], u1 = t[(up + 1) % 3];
        startingAt.emplace(key(d0, d1), segments.size());
        segments.push_back({key(d0, d1), key(u0, u1), cut(d0, d1)});
    }
    std::vector<SectionLoop> loops;
    std::vector<bool> used(segments.size(), false);
    for (size_t s = 0; s < segments.size(); ++s) {
        if (used[s]) continue;
        SectionLoop loop;
        size_t i = s;
        while (!used[i]) {
            used[i] = true;
            const auto& p = segments[i].start;
            if (loop.points.empty() || loop.points.back() != p) loop.points.push_back(p);
            const auto next = startingAt.find(segments[i].to);
            if (next == startingAt.end()) break;  // an open chain: only a mesh with holes
            i = next->second;
        }
        while (loop.points.size() > 1 && loop.points.front() == loop.points.back())
            loop.points.pop_back();
        if (loop.points.size() >= 3) loops.push_back(std::move(loop));
    }
    return loops;
}

}  // namespace kerf
