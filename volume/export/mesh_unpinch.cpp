// Edges of more than two faces undone where crease placement made them
// (volume/export/mesh_unpinch.h).
#include "volume/export/mesh_unpinch.h"

#include "volume/export/mesh_placement.h"
#include "volume/octree/surface_search.h"

#include <array>
#include <cstring>
#include <unordered_map>
#include <unordered_set>

namespace kerf {

namespace {

constexpr int kUnpinchRounds = 4;

/// A position as a reader stores it: three floats, -0 as +0.
using FloatPosition = std::array<float, 3>;

struct FloatPositionHash {
    size_t operator()(const FloatPosition& p) const {
        uint64_t h = 1469598103934665603ull;
        for (const float c : p) {
            uint32_t bits;
            std::memcpy(&bits, &c, 4);
            h = (h ^ bits) * 1099511628211ull;
        }
        return size_t(h);
    }
};

/// Each vertex's joined id: the first vertex at its position as a float. PLY and STL store
/// floats, and Assimp reads OBJ's decimals into floats too, so every reader of the file joins
/// vertices equal as floats. The key is the floats themselves: GCC 12.2 at -O2 compiles
/// `dvec3(double(float(x)), double(float(y)), ...)` to a copy of x and y (its SLP vectorizer
/// drops the round trip of a pair), which left vertices 2^-55 apart unjoined here.
std::vector<uint32_t> joinedIds(const std::vector<Vec3>& points) {
    std::unordered_map<FloatPosition, uint32_t, FloatPositionHash> first;
    first.reserve(points.size());
    std::vector<uint32_t> id(points.size());
    for (uint32_t i = 0; i < points.size(); ++i) {
        const Vec3& p = points[i];
        const FloatPosition asRead{float(p.x) + 0.0f, float(p.y) + 0.0f, float(p.z) + 0.0f};
        id[i] = first.emplace(asRead, i).first->second;
    }
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

/// Places again the vertices at the ends of crowded edges not placed again before: projected
/// along the gradient from OpenVDB's position, or, as a last resort, every such vertex at
/// OpenVDB's own position. Those are distinct, whereas two vertices projected along one
/// gradient (a flat face) can still land on one point. Returns how many were placed.
uint64_t placeAgain(const SampledField& field, const std::vector<Vec3>& lattice,
                    const std::vector<uint32_t>& id, const std::unordered_set<uint32_t>& ends,
                    bool lastResort, std::vector<uint8_t>& replaced, std::vector<Vec3>& points) {
    const MeshLattice& l = field.lattice;
    uint64_t moved = 0;
    for (uint32_t i = 0; i < points.size(); ++i) {
        if (!ends.count(id[i]) || (replaced[i] && !lastResort)) continue;
        replaced[i] = 1;
        const Vec3 p = modelFromIndex(l, lattice[i]);
        Vec3 placed;
        points[i] = !lastResort && rootAlongGradient(tapeNear(field, lattice[i]), p, l.voxel,
                                                     kPlacementRootTolerance * l.voxel, placed)
                        ? placed
                        : p;
        ++moved;
    }
    return moved;
}

}  // namespace

uint64_t crowdedEdges(const std::vector<Vec3>& points,
                      const std::vector<std::array<uint32_t, 3>>& triangles) {
    return crowded(joinedIds(points), triangles, nullptr);
}

UnpinchResult unpinchCreases(const SampledField& field, const std::vector<Vec3>& lattice,
                             std::vector<Vec3>& points,
                             const std::vector<std::array<uint32_t, 3>>& triangles) {
    std::vector<uint8_t> replaced(points.size(), 0);
    UnpinchResult result;
    bool lastResort = false;
    for (int round = 0;; ++round) {
        std::unordered_set<uint32_t> ends;
        const std::vector<uint32_t> id = joinedIds(points);
        result.crowdedLeft = crowded(id, triangles, &ends);
        if (result.crowdedLeft == 0 || lastResort) break;
        lastResort = round == kUnpinchRounds;
        if (placeAgain(field, lattice, id, ends, lastResort, replaced, points) == 0 &&
            !lastResort) {
            lastResort = true;
            placeAgain(field, lattice, id, ends, lastResort, replaced, points);
        }
    }
    for (const uint8_t r : replaced) result.replaced += r;
    return result;
}

}  // namespace kerf
