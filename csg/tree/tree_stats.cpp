// One post-order walk over a DAG of nodes with an explicit stack, memoised per node.
#include "csg/tree/tree_stats.h"

#include <algorithm>
#include <limits>
#include <unordered_map>

namespace kerf {

namespace {

constexpr int64_t kMax = std::numeric_limits<int64_t>::max();

int64_t saturatingAdd(int64_t a, int64_t b) { return a > kMax - b ? kMax : a + b; }

struct Memo {
    int64_t instances;
    int depth;
};

TreeStats treeStatsOf(const std::vector<const Node*>& roots) {
    TreeStats stats;
    std::unordered_map<const Node*, Memo> memo;
    std::vector<std::pair<const Node*, size_t>> stack;  // node, next child to visit
    for (const Node* root : roots) {
        if (!root) continue;
        if (memo.count(root)) {  // a subtree of an earlier root
            stats.instances = saturatingAdd(stats.instances, memo[root].instances);
            continue;
        }
        stack.push_back({root, 0});
        while (!stack.empty()) {
            auto& [node, next] = stack.back();
            const NodeSpan kids = node->children();
            if (next < kids.size()) {
                const Node* child = kids[next++].get();
                if (!memo.count(child)) stack.push_back({child, 0});
                continue;
            }
            // Every child is memoised: combine them.
            Memo m{kids.empty() ? 1 : 0, 1};
            for (const NodePtr& c : kids) {
                const Memo& cm = memo.at(c.get());
                m.instances = saturatingAdd(m.instances, cm.instances);
                m.depth = std::max(m.depth, cm.depth + 1);
            }
            ++stats.nodes;
            if (kids.empty()) ++stats.primitives;
            memo.emplace(node, m);
            stack.pop_back();
        }
        const Memo& r = memo.at(root);
        stats.instances = saturatingAdd(stats.instances, r.instances);
        stats.depth = std::max(stats.depth, r.depth);
    }
    stats.instancesSaturated = stats.instances == kMax;
    return stats;
}

}  // namespace

TreeStats treeStats(const std::vector<NodePtr>& roots) {
    std::vector<const Node*> raw;
    for (const NodePtr& r : roots) raw.push_back(r.get());
    return treeStatsOf(raw);
}

TreeStats treeStats(const Node& root) { return treeStatsOf({&root}); }

int64_t Node::primitiveCount() const { return treeStats(*this).instances; }
int Node::depth() const { return treeStats(*this).depth; }

}  // namespace kerf
