// The binary tree collapsed into 4-wide nodes (mesh/bvh4.h). Which inner child to open is
// chosen by surface area: the largest box is the one rays enter most often, so opening it
// saves the most node visits.
#include "mesh/bvh4.h"

#include <limits>

namespace kerf::bvh4 {

namespace {

using Node = TriangleBvh::Node;

double nodeHalfArea(const Node& n) {
    const double x = double(n.hi[0]) - n.lo[0], y = double(n.hi[1]) - n.lo[1],
                 z = double(n.hi[2]) - n.lo[2];
    return x * y + y * z + z * x;
}

struct Collapser {
    const std::vector<Node>& bin;
    std::vector<WideNode>& out;

    // Fills a new wide node with the given binary nodes as lanes (opening inner ones until
    // there are four) and returns its index.
    uint32_t emit(std::vector<uint32_t> lanes) {
        while (lanes.size() < 4) {
            int best = -1;
            double bestArea = -1.0;
            for (size_t k = 0; k < lanes.size(); ++k)
                if (bin[lanes[k]].count == 0 && nodeHalfArea(bin[lanes[k]]) > bestArea) {
                    bestArea = nodeHalfArea(bin[lanes[k]]);
                    best = int(k);
                }
            if (best < 0) break;
            const uint32_t open = lanes[size_t(best)];
            lanes[size_t(best)] = open + 1;  // the first child follows its parent
            lanes.insert(lanes.begin() + best + 1, bin[open].index);
        }
        const uint32_t self = uint32_t(out.size());
        out.emplace_back();
        {
            WideNode& w = out[self];
            constexpr float inf = std::numeric_limits<float>::infinity();
            for (int a = 0; a < 3; ++a)
                for (int k = 0; k < 4; ++k) {
                    w.lo[a][k] = inf;
                    w.hi[a][k] = -inf;
                }
            for (int k = 0; k < 4; ++k) {
                w.index[k] = 0;
                w.count[k] = 0;
            }
            w.lanes = uint8_t(lanes.size());
            for (int p = 0; p < 7; ++p) w.pad[p] = 0;
        }
        for (size_t k = 0; k < lanes.size(); ++k) {
            const Node& b = bin[lanes[k]];
            for (int a = 0; a < 3; ++a) {
                out[self].lo[a][k] = b.lo[a];
                out[self].hi[a][k] = b.hi[a];
            }
            if (b.count > 0) {
                out[self].index[k] = b.index;
                out[self].count[k] = b.count;
            } else {
                const uint32_t child = emit({lanes[k] + 1, b.index});  // may reallocate out
                out[self].index[k] = child;
            }
        }
        return self;
    }
};

}  // namespace

std::vector<WideNode> collapse(const std::vector<Node>& binary) {
    std::vector<WideNode> out;
    if (binary.empty()) return out;
    out.reserve(binary.size() / 2 + 1);
    Collapser c{binary, out};
    // A root leaf becomes the one lane of a wide root; else the root's two children start it.
    if (binary[0].count > 0)
        c.emit({0});
    else
        c.emit({1, binary[0].index});
    return out;
}

std::vector<TriPack> packLeaves(std::vector<WideNode>& nodes, const TriangleBvh::Tri* tris,
                                const uint32_t* triangleIndex) {
    std::vector<TriPack> packs;
    for (WideNode& n : nodes)  // root first, depth first: packs follow the walk order
        for (int k = 0; k < n.lanes; ++k) {
            if (n.count[k] == 0) continue;
            const uint32_t slot = n.index[k];
            n.index[k] = uint32_t(packs.size());
            for (uint32_t i = 0; i < n.count[k]; i += 4) {
                TriPack p{};
                for (int lane = 0; lane < 4; ++lane) {
                    // Unused lanes repeat the pack's first triangle: finite, never tested.
                    const uint32_t s = slot + i + (i + lane < n.count[k] ? uint32_t(lane) : 0u);
                    for (int vtx = 0; vtx < 3; ++vtx)
                        for (int a = 0; a < 3; ++a) p.p[vtx][a][lane] = tris[s].p[vtx][a];
                    p.triangle[lane] = triangleIndex[s];
                }
                packs.push_back(p);
            }
        }
    return packs;
}

}  // namespace kerf::bvh4
