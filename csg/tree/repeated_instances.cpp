#include "csg/tree/repeated_instances.h"

#include "csg/tree/node_kind.h"

#include <cstdint>
#include <cstring>
#include <unordered_map>
#include <variant>

namespace kerf {

namespace {

/// Transform and material nodes are the wrappers an instance is made of; everything else ends
/// the chain (a Boolean or primitive below them is compared by identity).
bool isInstanceWrapper(const Node& n) {
    return n.kind() == NodeKind::Transform || n.kind() == NodeKind::Material;
}

void mixBits(uint64_t& h, uint64_t bits) {
    h ^= bits + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
}

void mixDouble(uint64_t& h, double d) {
    uint64_t bits = 0;
    std::memcpy(&bits, &d, sizeof bits);
    mixBits(h, bits);
}

void mixAffine(uint64_t& h, const Affine& a) {
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) mixDouble(h, a.linear[c][r]);
    for (int r = 0; r < 3; ++r) mixDouble(h, a.offset[r]);
}

bool sameBits(const Affine& a, const Affine& b) {
    return std::memcmp(&a.linear, &b.linear, sizeof a.linear) == 0 &&
           std::memcmp(&a.offset, &b.offset, sizeof a.offset) == 0;
}

/// Equal wrappers: the same kind with the same map or the same material.
bool sameWrapper(const Node& a, const Node& b) {
    if (a.kind() != b.kind()) return false;
    const NodeParams pa = a.params(), pb = b.params();
    if (a.kind() == NodeKind::Transform)
        return sameBits(std::get<TransformParams>(pa).worldFromLocal,
                        std::get<TransformParams>(pb).worldFromLocal);
    return std::get<MaterialParams>(pa).material == std::get<MaterialParams>(pb).material;
}

uint64_t instanceHash(const Node& node) {
    uint64_t h = 0;
    const Node* n = &node;
    for (; isInstanceWrapper(*n); n = n->children()[0].get()) {
        mixBits(h, static_cast<uint64_t>(n->kind()));
        const NodeParams p = n->params();
        if (n->kind() == NodeKind::Transform)
            mixAffine(h, std::get<TransformParams>(p).worldFromLocal);
        else
            mixBits(h, static_cast<uint64_t>(std::get<MaterialParams>(p).material));
    }
    mixBits(h, reinterpret_cast<uintptr_t>(n));
    return h;
}

}  // namespace

bool sameInstance(const Node& a, const Node& b) {
    const Node* x = &a;
    const Node* y = &b;
    while (x != y) {
        if (!isInstanceWrapper(*x) || !isInstanceWrapper(*y) || !sameWrapper(*x, *y)) return false;
        x = x->children()[0].get();
        y = y->children()[0].get();
    }
    return true;
}

std::vector<NodePtr> withoutRepeatedInstances(BoolOp op, std::vector<NodePtr> children) {
    if (op == BoolOp::Xor || children.size() < 2) return children;
    // A difference's first operand is not one of the subtracted: it is never dropped, and it
    // does not make a subtracted copy of itself go (A − A stays empty).
    const size_t first = op == BoolOp::Difference ? 1 : 0;
    std::unordered_multimap<uint64_t, size_t> seen;  // hash → index into kept
    std::vector<NodePtr> kept(children.begin(), children.begin() + first);
    for (size_t i = first; i < children.size(); ++i) {
        const uint64_t h = instanceHash(*children[i]);
        bool repeat = false;
        for (auto [it, end] = seen.equal_range(h); it != end && !repeat; ++it)
            repeat = sameInstance(*kept[it->second], *children[i]);
        if (repeat) continue;
        seen.emplace(h, kept.size());
        kept.push_back(std::move(children[i]));
    }
    return kept;
}

}  // namespace kerf
