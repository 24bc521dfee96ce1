// Definitions in dependency order: the names each definition uses, then Tarjan's algorithm
// with an explicit stack, so neither long chains nor long cycles of names recurse.
#include "lang/definition_order.h"

#include "scene/limits.h"

#include <algorithm>
#include <unordered_map>

namespace kerf {

namespace {

struct Use {
    int target;
    SourcePos loc;
};

/// The definitions a definition uses, in the order written, each once. The walk keeps its
/// own stack: a statement nests at most kMaxNesting solids, but expressions can be
/// kMaxExpressionDepth deep.
class UseCollector {
public:
    UseCollector(const std::map<std::string, const Statement*>& lets,
                 const std::map<std::string, const Statement*>& solids,
                 const std::unordered_map<const Statement*, int>& index)
        : mLets(lets), mSolids(solids), mIndex(index) {}

    std::vector<Use> collect(const Statement& s) {
        std::vector<Use> uses;
        mExprs.clear();
        mSolidStack.clear();
        if (s.expr) mExprs.push_back(s.expr);
        if (s.solid) mSolidStack.push_back(s.solid);
        while (!mExprs.empty() || !mSolidStack.empty()) {
            if (!mSolidStack.empty()) {
                const Solid* solid = mSolidStack.back();
                mSolidStack.pop_back();
                if (solid->kind == Solid::Kind::Reference) {
                    add(mSolids, solid->name, solid->loc, uses);
                    if (!mSolids.count(solid->name))
                        add(mLets, solid->name, solid->loc, uses);  // a let holding a solid
                }
                for (const Property& p : solid->properties) {
                    if (p.expr) mExprs.push_back(p.expr);
                    if (p.solid) mSolidStack.push_back(p.solid);
                }
                for (const Modifier& m : solid->modifiers) {
                    for (const Expr& a : m.args) mExprs.push_back(&a);
                    if (m.pattern) mSolidStack.push_back(m.pattern);
                }
                for (const Solid& c : solid->children) mSolidStack.push_back(&c);
                continue;
            }
            const Expr* e = mExprs.back();
            mExprs.pop_back();
            if (e->kind == Expr::Kind::Name) {
                add(mLets, e->name(), e->loc, uses);
                add(mSolids, e->name(), e->loc, uses);  // a solid used as a value
            }
            if (e->kind == Expr::Kind::SolidValue) mSolidStack.push_back(e->solid);
            for (const Expr& a : e->args()) mExprs.push_back(&a);
        }
        // The walk popped from the back; uses in the order written read best in messages.
        std::reverse(uses.begin(), uses.end());
        std::vector<Use> unique;
        for (const Use& u : uses)
            if (std::none_of(unique.begin(), unique.end(),
                             [&](const Use& v) { return v.target == u.target; }))
                unique.push_back(u);
        return unique;
    }

private:
    void add(const std::map<std::string, const Statement*>& table, const std::string& name,
             SourcePos loc, std::vector<Use>& uses) {
        const auto it = table.find(name);
        if (it != table.end()) uses.push_back({mIndex.at(it->second), loc});
    }

    const std::map<std::string, const Statement*>& mLets;
    const std::map<std::string, const Statement*>& mSolids;
    const std::unordered_map<const Statement*, int>& mIndex;
    std::vector<const Expr*> mExprs;
    std::vector<const Solid*> mSolidStack;
};

}  // namespace

std::vector<OrderedDefinition> definitionOrder(
    const std::map<std::string, const Statement*>& lets,
    const std::map<std::string, const Statement*>& solids, const DiagnosticSink& sink) {
    // Definitions in statement order (line and column), so the walk (and what it reports)
    // follows the file.
    std::vector<std::pair<std::pair<int, int>, const Statement*>> keyed;
    for (const auto* table : {&lets, &solids})
        for (const auto& [name, def] : *table) {
            const SourceLoc at = sink.locate(def->loc);
            keyed.push_back({{at.line, at.col}, def});
        }
    std::stable_sort(keyed.begin(), keyed.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<const Statement*> defs;
    defs.reserve(keyed.size());
    for (const auto& k : keyed) defs.push_back(k.second);
    keyed = {};
    std::unordered_map<const Statement*, int> index;
    for (size_t i = 0; i < defs.size(); ++i) index[defs[i]] = static_cast<int>(i);
    const int n = static_cast<int>(defs.size());
    std::vector<std::vector<Use>> uses(n);
    UseCollector collector(lets, solids, index);
    for (int i = 0; i < n; ++i) uses[i] = collector.collect(*defs[i]);

    // Tarjan's algorithm; `frames` is the call stack (vertex, next use to follow).
    std::vector<int> order(n, -1), low(n, 0);
    std::vector<char> onStack(n, 0), tainted(n, 0);
    std::vector<int> sccStack, level(n, 1);
    std::vector<std::pair<int, size_t>> frames;
    std::vector<OrderedDefinition> out;
    int counter = 0;
    for (int root = 0; root < n; ++root) {
        if (order[root] >= 0) continue;
        frames.push_back({root, 0});
        order[root] = low[root] = counter++;
        sccStack.push_back(root);
        onStack[root] = 1;
        while (!frames.empty()) {
            auto& [v, next] = frames.back();
            if (next < uses[v].size()) {
                const int w = uses[v][next++].target;
                if (order[w] < 0) {
                    order[w] = low[w] = counter++;
                    sccStack.push_back(w);
                    onStack[w] = 1;
                    frames.push_back({w, 0});
                } else if (onStack[w]) {
                    low[v] = std::min(low[v], order[w]);
                }
                continue;
            }
            const int done = v;
            frames.pop_back();
            if (!frames.empty())
                low[frames.back().first] = std::min(low[frames.back().first], low[done]);
            if (low[done] != order[done]) continue;
            // `done` roots a component: every definition it uses is already emitted.
            std::vector<int> component;
            int w;
            do {
                w = sccStack.back();
                sccStack.pop_back();
                onStack[w] = 0;
                component.push_back(w);
            } while (w != done);
            const bool selfUse = std::any_of(uses[done].begin(), uses[done].end(),
                                             [&](const Use& u) { return u.target == done; });
            bool bad = component.size() > 1 || selfUse;
            for (const int c : component)
                for (const Use& u : uses[c]) bad = bad || tainted[u.target];
            if (bad) {
                for (const int c : component) tainted[c] = 1;
                continue;
            }
            OrderedDefinition d;
            d.def = defs[done];
            for (const Use& u : uses[done]) {
                d.uses.push_back(defs[u.target]);
                if (level[u.target] + 1 > d.level) {
                    d.level = level[u.target] + 1;
                    d.tooDeepAt = u.loc;
                }
            }
            level[done] = d.level;
            d.firstTooDeep = d.level == kMaxNameDepth + 1;
            out.push_back(std::move(d));
        }
    }
    return out;
}

}  // namespace kerf
