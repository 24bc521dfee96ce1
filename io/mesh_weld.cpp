// Exact welding of a mesh's written positions (io/mesh_weld.h).
#include "io/mesh_weld.h"

#include "io/mesh_writers.h"

#include <array>
#include <cstring>
#include <unordered_map>

namespace kerf {
namespace {

using WeldKey = std::array<uint64_t, 3>;

struct WeldKeyHash {
    size_t operator()(const WeldKey& k) const {
        uint64_t h = 1469598103934665603ull;
        for (const uint64_t w : k) h = (h ^ w) * 1099511628211ull;
        return size_t(h ^ (h >> 29));
    }
};

/// The bits of a coordinate as written: the double, or its float rounding; +0 for -0.
uint64_t weldCoordinateBits(double v, bool asFloat) {
    const double written = (asFloat ? double(float(v)) : v) + 0.0;
    uint64_t bits = 0;
    std::memcpy(&bits, &written, sizeof bits);
    return bits;
}

}  // namespace

WeldedMesh weldWrittenPositions(const MeshArrays& mesh, bool asFloat) {
    WeldedMesh out;
    std::unordered_map<WeldKey, uint32_t, WeldKeyHash> byPosition;
    byPosition.reserve(mesh.vertexCount);
    std::vector<uint32_t> newIndex(mesh.vertexCount);
    for (size_t i = 0; i < mesh.vertexCount; ++i) {
        WeldKey key;
        for (size_t a = 0; a < 3; ++a) key[a] = weldCoordinateBits(mesh.xyz[3 * i + a], asFloat);
        const auto [it, added] = byPosition.emplace(key, uint32_t(out.xyz.size() / 3));
        if (added)
            for (size_t a = 0; a < 3; ++a) out.xyz.push_back(mesh.xyz[3 * i + a]);
        newIndex[i] = it->second;
    }
    out.indices.reserve(3 * mesh.triangleCount);
    for (size_t t = 0; t < mesh.triangleCount; ++t) {
        const uint32_t a = newIndex[mesh.indices[3 * t]], b = newIndex[mesh.indices[3 * t + 1]],
                       c = newIndex[mesh.indices[3 * t + 2]];
        if (a == b || b == c || c == a) continue;
        out.indices.insert(out.indices.end(), {a, b, c});
    }
    return out;
}

}  // namespace kerf
