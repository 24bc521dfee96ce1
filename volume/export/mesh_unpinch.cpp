// Edges of more than two faces undone where crease placement made them
// (volume/export/mesh_unpinch.h).
#include "volume/export/mesh_unpinch.h"

#include "volume/export/mesh_placement.h"
#include "volume/octree/surface_search.h"

#include <cstring>
#include <unordered_map>
#include <unordered_set>

namespace kerf {

namespace {

constexpr int kUnpinchRounds = 4;

struct PositionHash {
    size_t operator()(const Vec3& p) const {
        uint64_t h = 1469598103934665603ull;
        for (int a = 0; a < 3; ++a) {
            const double c = p[a] + 0.0;  // -0 and +0 are one position
            uint64_t bits;
            std::memcpy(&bits, &c, 8);
            h = (h ^ bits) * 1099511628211ull;
        }
        return size_t(h);
    }
};
struct PositionEqual {
    bool operator()(const Vec3& a, const Vec3& b) const {
        return a.x == b.x && a.y == b.y && a.z == b.z;
    }
};

/// Each vertex's joined id: the first vertex at its position.
std::vector<uint32_t> joinedIds(const std::vector<Vec3>& points) {
    std::unordered_map<Vec3, uint32_t, PositionHash, PositionEqual> first;
    first.reserve(points.size());
    std::vector<uint32_t> id(points.size());
    for (uint32_t i = 0; i < points.size(); ++i) id[i] = first.emplace(points[i], i).first->second;
    return id;
}

/// The joined ids at the ends of edges shared by more than two faces, and how many such edges.
uint64_t crowded(const std::vector<uint32_t>& id,
                 const std::vector<std::array<uint32_t, 3>>& triangles,
                 std::unordered_set<uint32_t>* ends) {
    std::unordered_map<uint64_t, uint32_t> faces;
    faces.reserve(3 * triangles.size());
    for (const auto& t : triangles) {
        const uint32_t a = id[t[0]], b = id[t[1]], c = id[t[2]];
        if (a == b || b == c || c == a) continue;
        for (const auto& [u, v] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}})
            ++faces[uint64_t(std::min(u, v)) << 32 | std::max(u, v)];
    }
    uint64_t n = 0;
    for (const auto& [edge, count] : faces) {
        if (count <= 2) continue;
        ++n;
        if (ends) {
            ends->insert(uint32_t(edge >> 32));
            ends->insert(uint32_t(edge & 0xffffffffu));
        }
    }
    return n;
}

}  // namespace

uint64_t crowdedEdges(const std::vector<Vec3>& points,
                      const std::vector<std::array<uint32_t, 3>>& triangles) {
    return crowded(joinedIds(points), triangles, nullptr);
}

UnpinchResult unpinchCreases(const SampledField& field, const std::vector<Vec3>& lattice,
                             std::vector<Vec3>& points,
                             const std::vector<std::array<uint32_t, 3>>& triangles) {
    const MeshLattice& l = field.lattice;
    std::vector<uint8_t> replaced(points.size(), 0);
    UnpinchResult result;
    for (int round = 0;; ++round) {
        std::unordered_set<uint32_t> ends;
        const std::vector<uint32_t> id = joinedIds(points);
        result.crowdedLeft = crowded(id, triangles, &ends);
        if (result.crowdedLeft == 0 || round == kUnpinchRounds) break;
        uint64_t moved = 0;
        for (uint32_t i = 0; i < points.size(); ++i) {
            if (replaced[i] || !ends.count(id[i])) continue;
            replaced[i] = 1;
            const Vec3 p = modelFromIndex(l, lattice[i]);
            Vec3 placed;
            const Tape& tape = tapeNear(field, lattice[i]);
            points[i] =
                rootAlongGradient(tape, p, l.voxel, kPlacementRootTolerance * l.voxel, placed)
                    ? placed
                    : p;
            ++moved;
        }
        result.replaced += moved;
        if (moved == 0) break;
    }
    return result;
}

}  // namespace kerf
