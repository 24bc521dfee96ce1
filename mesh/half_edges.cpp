// Half-edges and the validation report. Twins are found through a hash map keyed by the
// directed edge (origin, destination), which also counts how many triangles run each
// direction; an undirected edge is classified once, at the first half-edge that uses it, so
// counts and the first bad edge do not depend on the map's iteration order.
#include "mesh/half_edges.h"

#include <algorithm>
#include <cstring>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

namespace kerf {
namespace {

struct PositionHash {
    size_t operator()(const Vec3& p) const {
        uint64_t h = 1469598103934665603ull;
        for (int i = 0; i < 3; ++i) {
            const double z = p[i] == 0.0 ? 0.0 : p[i];  // -0 and +0 are one position
            uint64_t bits;
            std::memcpy(&bits, &z, sizeof bits);
            h = (h ^ bits) * 1099511628211ull;
            h ^= h >> 29;
        }
        return static_cast<size_t>(h);
    }
};

uint64_t directedKey(uint32_t from, uint32_t to) { return (uint64_t(from) << 32) | to; }

struct DirectedUse {
    uint32_t first;  ///< the lowest half-edge running this way
    uint32_t count;  ///< how many half-edges run this way
};

using DirectedMap = std::unordered_map<uint64_t, DirectedUse>;

bool repeatsVertex(const HalfEdges& he, uint32_t t) {
    const uint32_t a = he.origin[3 * t], b = he.origin[3 * t + 1], c = he.origin[3 * t + 2];
    return a == b || b == c || a == c;
}

/// The shared work of both entry points: welded origins and the directed-edge counts.
HalfEdges build(const TriangleMesh& mesh, DirectedMap& directed) {
    HalfEdges he;
    he.weld.resize(mesh.positions.size());
    std::unordered_map<Vec3, uint32_t, PositionHash> firstAt;
    firstAt.reserve(mesh.positions.size());
    for (uint32_t v = 0; v < mesh.positions.size(); ++v)
        he.weld[v] = firstAt.try_emplace(mesh.positions[v], v).first->second;

    const size_t n = 3 * mesh.triangles.size();
    he.origin.resize(n);
    he.twin.assign(n, HalfEdges::kNone);
    for (size_t t = 0; t < mesh.triangles.size(); ++t)
        for (int c = 0; c < 3; ++c) {
            const uint32_t v = mesh.triangles[t][c];
            if (v >= mesh.positions.size())
                throw std::out_of_range("triangle " + std::to_string(t) + " uses vertex " +
                                        std::to_string(v) + " of " +
                                        std::to_string(mesh.positions.size()));
            he.origin[3 * t + c] = he.weld[v];
        }

    directed.reserve(n);
    for (uint32_t h = 0; h < n; ++h) {
        if (repeatsVertex(he, h / 3)) continue;
        auto [it, inserted] = directed.try_emplace(
            directedKey(he.origin[h], he.origin[HalfEdges::next(h)]), DirectedUse{h, 0});
        ++it->second.count;
    }
    // A twin only where exactly one triangle runs each way: a proper manifold, oriented edge.
    for (uint32_t h = 0; h < n; ++h) {
        if (repeatsVertex(he, h / 3)) continue;
        const uint32_t a = he.origin[h], b = he.origin[HalfEdges::next(h)];
        const auto ab = directed.find(directedKey(a, b));
        const auto ba = directed.find(directedKey(b, a));
        if (ba != directed.end() && ab->second.count == 1 && ba->second.count == 1)
            he.twin[h] = ba->second.first;
    }
    return he;
}

}  // namespace

HalfEdges buildHalfEdges(const TriangleMesh& mesh) {
    DirectedMap directed;
    return build(mesh, directed);
}

MeshReport validateMesh(const TriangleMesh& mesh) {
    DirectedMap directed;
    const HalfEdges he = build(mesh, directed);
    MeshReport r;
    r.triangles = mesh.triangles.size();

    std::vector<bool> used(mesh.positions.size(), false);
    for (uint32_t h = 0; h < he.origin.size(); ++h) used[he.origin[h]] = true;
    r.vertices = static_cast<size_t>(std::count(used.begin(), used.end(), true));

    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const Vec3& p0 = mesh.positions[mesh.triangles[t][0]];
        const Vec3& p1 = mesh.positions[mesh.triangles[t][1]];
        const Vec3& p2 = mesh.positions[mesh.triangles[t][2]];
        // Zero area as computed in double; the welded-vertex test catches exact repeats.
        if (repeatsVertex(he, static_cast<uint32_t>(t)) ||
            glm::cross(p1 - p0, p2 - p0) == Vec3(0.0))
            ++r.degenerateTriangles;
    }

    for (uint32_t h = 0; h < he.origin.size(); ++h) {
        if (repeatsVertex(he, h / 3)) continue;
        const uint32_t a = he.origin[h], b = he.origin[HalfEdges::next(h)];
        const DirectedUse ab = directed.find(directedKey(a, b))->second;
        const auto baIt = directed.find(directedKey(b, a));
        const DirectedUse ba =
            baIt == directed.end() ? DirectedUse{HalfEdges::kNone, 0} : baIt->second;
        if (h != std::min(ab.first, ba.first)) continue;  // this undirected edge is counted
        const uint32_t uses = ab.count + ba.count;
        std::optional<EdgeFault> fault;
        if (uses == 1) {
            ++r.boundaryEdges;
            fault = EdgeFault::Boundary;
        } else if (uses > 2) {
            ++r.nonManifoldEdges;
            fault = EdgeFault::NonManifold;
        } else if (ab.count == 2) {
            ++r.inconsistentEdges;
            fault = EdgeFault::Inconsistent;
        }
        if (fault && !r.firstBadEdge) {
            const uint32_t va = mesh.triangles[h / 3][h % 3];
            const uint32_t vb = mesh.triangles[h / 3][HalfEdges::next(h) % 3];
            r.firstBadEdge = BadEdge{*fault, va, vb, mesh.positions[va], mesh.positions[vb]};
        }
    }
    // A mesh of nothing but degenerate triangles encloses no volume, whatever its edges say.
    r.solid = r.triangles > r.degenerateTriangles && r.boundaryEdges == 0 &&
              r.nonManifoldEdges == 0 && r.inconsistentEdges == 0;
    return r;
}

const char* edgeFaultName(EdgeFault fault) {
    switch (fault) {
        case EdgeFault::Boundary: return "boundary";
        case EdgeFault::NonManifold: return "non-manifold";
        case EdgeFault::Inconsistent: return "inconsistently oriented";
    }
    return "bad";
}

std::string describeBadEdge(const BadEdge& e) {
    std::ostringstream s;
    s.precision(17);
    s << edgeFaultName(e.fault) << " edge from vertex " << e.a << " <" << e.pa.x << ", " << e.pa.y
      << ", " << e.pa.z << "> to vertex " << e.b << " <" << e.pb.x << ", " << e.pb.y << ", "
      << e.pb.z << ">";
    return s.str();
}

}  // namespace kerf
