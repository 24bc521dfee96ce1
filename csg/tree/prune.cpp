// Pruning a tree over a box: interval classification decides which children matter, then the
// node is rebuilt over the ones that do (Node::withChildren), bottom up.
#include "csg/tree/prune.h"

#include <algorithm>
#include <cmath>
#include <variant>

#include "csg/tape/tape.h"
#include "csg/tree/solids.h"

namespace kerf {
namespace {

IntervalVec3 asIntervals(const Bounds3& b) {
    return {Interval(b.lo.x, b.hi.x), Interval(b.lo.y, b.hi.y), Interval(b.lo.z, b.hi.z)};
}

Pruned empty() { return {PruneState::Empty, nullptr}; }
Pruned full() { return {PruneState::Full, nullptr}; }
Pruned partial(NodePtr n) { return {PruneState::Partial, std::move(n)}; }

/// `node` over new children: itself when they are the children it has (nothing pruned).
NodePtr rebuilt(const NodePtr& node, std::vector<NodePtr> kids) {
    const NodeSpan old = node->children();
    bool same = kids.size() == old.size();
    for (size_t i = 0; same && i < kids.size(); ++i) same = kids[i] == old[i];
    return same ? node : node->withChildren(std::move(kids));
}

/// The box in the child's space of a transform: each local coordinate is an affine form of
/// the world ones, evaluated on intervals (outward rounding), so every point of the box maps
/// inside it.
Bounds3 localBox(const Affine& localFromWorld, const Bounds3& box) {
    const Interval in[3] = {Interval(box.lo.x, box.hi.x), Interval(box.lo.y, box.hi.y),
                            Interval(box.lo.z, box.hi.z)};
    Bounds3 out;
    for (int row = 0; row < 3; ++row) {
        Interval acc(localFromWorld.offset[row]);
        for (int col = 0; col < 3; ++col) {
            const double m = localFromWorld.linear[col][row];
            if (m != 0.0) acc = acc + Interval(m) * in[col];
        }
        // Padded: the point map rounds once more than this enclosure accounts for.
        const double pad = 0x1p-40 * std::fmax(std::fabs(acc.lo), std::fabs(acc.hi));
        out.lo[row] = acc.lo - pad;
        out.hi[row] = acc.hi + pad;
    }
    return out;
}

Pruned prunedImplicit(const NodePtr& node, const Bounds3& box) {
    const ImplicitParams p = std::get<ImplicitParams>(node->params());
    // Outside the bound the node is outside whatever the tape says: only the overlap matters.
    const Bounds3 overlap = Bounds3::overlap(box, p.bound);
    if (overlap.empty()) return empty();
    const IntervalVec3 region = asIntervals(overlap);
    std::vector<Choice> choices;
    const Interval f = p.tape->evalInterval(region.x, region.y, region.z, choices);
    const Classification c = f.classify();
    if (c == Classification::Empty) return empty();
    // Full only where the whole box is within the bound (beyond it the node is outside).
    const bool withinBound = overlap.lo == box.lo && overlap.hi == box.hi;
    if (c == Classification::Filled && withinBound) return full();
    // Most cells decide no min or max: then there is nothing to simplify, and no new tape.
    if (std::all_of(choices.begin(), choices.end(), [](Choice x) { return x == Choice::Both; }))
        return partial(node);
    std::shared_ptr<const Tape> shorter = p.tape->simplified(choices);
    if (shorter->size() == p.tape->size()) return partial(node);
    return partial(withImplicitFunction(*node, std::move(shorter)));
}

Pruned prunedBoolean(const NodePtr& node, const Bounds3& box) {
    const NodeKind kind = node->kind();
    const NodeSpan kids = node->children();
    std::vector<NodePtr> kept;
    switch (kind) {
        case NodeKind::Union:
            for (const NodePtr& c : kids) {
                const Pruned r = pruned(c, box);
                if (r.state == PruneState::Full) return full();
                if (r.state == PruneState::Partial) kept.push_back(r.node);
            }
            if (kept.empty()) return empty();
            break;
        case NodeKind::Intersection:
            for (const NodePtr& c : kids) {
                const Pruned r = pruned(c, box);
                if (r.state == PruneState::Empty) return empty();
                if (r.state == PruneState::Partial) kept.push_back(r.node);
            }
            if (kept.empty()) return full();
            break;
        case NodeKind::Difference: {
            const Pruned body = pruned(kids[0], box);
            if (body.state == PruneState::Empty) return empty();
            // A Full body has no node of its own: the original stands in for it.
            kept.push_back(body.state == PruneState::Full ? kids[0] : body.node);
            for (size_t i = 1; i < kids.size(); ++i) {
                const Pruned r = pruned(kids[i], box);
                if (r.state == PruneState::Full) return empty();
                if (r.state == PruneState::Partial) kept.push_back(r.node);
            }
            if (kept.size() == 1 && body.state == PruneState::Full) return full();
            break;
        }
        case NodeKind::Xor: {
            int fullCount = 0, partialCount = 0;
            for (const NodePtr& c : kids) {
                const Pruned r = pruned(c, box);
                if (r.state == PruneState::Empty) continue;
                // A Full child flips inside and outside: it stays, as the original.
                if (r.state == PruneState::Full)
                    ++fullCount, kept.push_back(c);
                else
                    ++partialCount, kept.push_back(r.node);
            }
            if (partialCount == 0) return fullCount % 2 == 1 ? full() : empty();
            break;
        }
        default: return partial(node);
    }
    if (kept.size() == 1) return partial(kept[0]);
    return partial(rebuilt(node, std::move(kept)));
}

}  // namespace

Pruned pruned(const NodePtr& node, const Bounds3& box) {
    if (Bounds3::overlap(node->bounds(), box).empty()) return empty();
    // Each node is evaluated over the box once: implicit leaves and closed primitives by
    // their own enclosure, transforms, materials and Booleans through their children, whose
    // states decide theirs (the same classification as the node's own combined interval,
    // which would evaluate every child a second time).
    switch (node->kind()) {
        case NodeKind::Implicit: return prunedImplicit(node, box);
        case NodeKind::Transform:
        case NodeKind::Material: {
            const NodePtr& child = node->children()[0];
            const Bounds3 childBox =
                node->kind() == NodeKind::Transform
                    ? localBox(std::get<TransformParams>(node->params()).localFromWorld, box)
                    : box;
            const Pruned r = pruned(child, childBox);
            if (r.state != PruneState::Partial) return r;
            return partial(rebuilt(node, {r.node}));
        }
        case NodeKind::Union:
        case NodeKind::Intersection:
        case NodeKind::Difference:
        case NodeKind::Xor: return prunedBoolean(node, box);
        default: break;  // closed-form primitives: nothing to simplify
    }
    switch (node->valueInterval(asIntervals(box)).classify()) {
        case Classification::Empty: return empty();
        case Classification::Filled: return full();
        case Classification::Ambiguous: break;
    }
    return partial(node);
}

namespace {

bool decidesChoices(const Tape& tape) {
    for (const TapeInstr& in : tape.instrs())
        if (in.op == Op::Min || in.op == Op::Max || in.op == Op::Abs) return true;
    return false;
}

/// prunedImplicit over many boxes for a tape with nothing to simplify: the same overlap with
/// the bound, the same enclosure (evaluated four boxes at a time), the same states.
void prunedImplicitMany(const NodePtr& node, const Bounds3* boxes, int count, Pruned* out) {
    const ImplicitParams p = std::get<ImplicitParams>(node->params());
    Interval x[kPrunedManyMax], y[kPrunedManyMax], z[kPrunedManyMax], f[kPrunedManyMax];
    bool within[kPrunedManyMax];
    int lanes[kPrunedManyMax];
    int n = 0;
    for (int k = 0; k < count; ++k) {
        const Bounds3 overlap = Bounds3::overlap(boxes[k], p.bound);
        if (overlap.empty()) {
            out[k] = empty();
            continue;
        }
        const IntervalVec3 region = asIntervals(overlap);
        x[n] = region.x, y[n] = region.y, z[n] = region.z;
        within[n] = overlap.lo == boxes[k].lo && overlap.hi == boxes[k].hi;
        lanes[n++] = k;
    }
    int i = 0;
    for (; i + 4 <= n; i += 4) p.tape->evalInterval4(x + i, y + i, z + i, f + i);
    for (; i < n; ++i) f[i] = p.tape->evalInterval(x[i], y[i], z[i]);
    for (int i = 0; i < n; ++i) {
        const Classification c = f[i].classify();
        out[lanes[i]] = c == Classification::Empty                 ? empty()
                        : c == Classification::Filled && within[i] ? full()
                                                                   : partial(node);
    }
}

}  // namespace

void prunedMany(const NodePtr& node, const Bounds3* boxes, int count, Pruned* out) {
    const NodeKind kind = node->kind();
    const bool wrapper = kind == NodeKind::Transform || kind == NodeKind::Material;
    const bool batchable =
        wrapper || (kind == NodeKind::Implicit &&
                    !decidesChoices(*std::get<ImplicitParams>(node->params()).tape));
    if (!batchable || count > kPrunedManyMax) {
        for (int k = 0; k < count; ++k) out[k] = pruned(node, boxes[k]);
        return;
    }
    // As pruned(): a box the node's bounds miss is empty.
    Bounds3 inner[kPrunedManyMax];
    Pruned innerOut[kPrunedManyMax];
    int lanes[kPrunedManyMax];
    int n = 0;
    for (int k = 0; k < count; ++k) {
        if (Bounds3::overlap(node->bounds(), boxes[k]).empty()) {
            out[k] = empty();
            continue;
        }
        inner[n] = boxes[k];
        lanes[n++] = k;
    }
    if (kind == NodeKind::Implicit) {
        prunedImplicitMany(node, inner, n, innerOut);
        for (int i = 0; i < n; ++i) out[lanes[i]] = innerOut[i];
        return;
    }
    const NodePtr& child = node->children()[0];
    if (kind == NodeKind::Transform) {
        const Affine localFromWorld = std::get<TransformParams>(node->params()).localFromWorld;
        for (int i = 0; i < n; ++i) inner[i] = localBox(localFromWorld, inner[i]);
    }
    prunedMany(child, inner, n, innerOut);
    for (int i = 0; i < n; ++i) {
        const Pruned& r = innerOut[i];
        out[lanes[i]] = r.state != PruneState::Partial ? r : partial(rebuilt(node, {r.node}));
    }
}

}  // namespace kerf
