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

/// Definitions in statement order (line and column), so the walk (and what it reports)
/// follows the file.
std::vector<const Statement*> definitionsInFileOrder(
    const std::map<std::string, const Statement*>& lets,
    const std::map<std::string, const Statement*>& solids, const DiagnosticSink& sink) {
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
    return defs;
}

/// Tarjan's algorithm over the use graph; `frames` is the call stack (vertex, next use to
/// follow). Emits each definition outside every cycle after all it uses; a definition in a
/// cycle, or using one, is left out.
class DependencyOrder {
public:
    DependencyOrder(const std::vector<const Statement*>& defs,
                    const std::vector<std::vector<Use>>& uses)
        : mDefs(defs),
          mUses(uses),
          mOrder(defs.size(), -1),
          mLow(defs.size(), 0),
          mOnStack(defs.size(), 0),
          mTainted(defs.size(), 0),
          mLevel(defs.size(), 1) {}

    std::vector<OrderedDefinition> run() {
        const int n = static_cast<int>(mDefs.size());
        for (int root = 0; root < n; ++root) {
            if (mOrder[root] >= 0) continue;
            enter(root);
            while (!mFrames.empty()) {
                auto& [v, next] = mFrames.back();
                if (next < mUses[v].size()) {
                    const int w = mUses[v][next++].target;
                    if (mOrder[w] < 0) {
                        enter(w);
                    } else if (mOnStack[w]) {
                        mLow[v] = std::min(mLow[v], mOrder[w]);
                    }
                    continue;
                }
                const int done = v;
                mFrames.pop_back();
                if (!mFrames.empty())
                    mLow[mFrames.back().first] = std::min(mLow[mFrames.back().first], mLow[done]);
                if (mLow[done] == mOrder[done]) closeComponent(done);
            }
        }
        return std::move(mOut);
    }

private:
    void enter(int v) {
        mOrder[v] = mLow[v] = mCounter++;
        mSccStack.push_back(v);
        mOnStack[v] = 1;
        mFrames.push_back({v, 0});
    }

    /// `done` roots a component: every definition it uses is already emitted.
    void closeComponent(int done) {
        std::vector<int> component;
        int w;
        do {
            w = mSccStack.back();
            mSccStack.pop_back();
            mOnStack[w] = 0;
            component.push_back(w);
        } while (w != done);
        const bool selfUse = std::any_of(mUses[done].begin(), mUses[done].end(),
                                         [&](const Use& u) { return u.target == done; });
        bool bad = component.size() > 1 || selfUse;
        for (const int c : component)
            for (const Use& u : mUses[c]) bad = bad || mTainted[u.target];
        if (bad) {
            for (const int c : component) mTainted[c] = 1;
            return;
        }
        OrderedDefinition d;
        d.def = mDefs[done];
        for (const Use& u : mUses[done]) {
            d.uses.push_back(mDefs[u.target]);
            if (mLevel[u.target] + 1 > d.level) {
                d.level = mLevel[u.target] + 1;
                d.tooDeepAt = u.loc;
            }
        }
        mLevel[done] = d.level;
        d.firstTooDeep = d.level == kMaxNameDepth + 1;
        mOut.push_back(std::move(d));
    }

    const std::vector<const Statement*>& mDefs;
    const std::vector<std::vector<Use>>& mUses;
    std::vector<int> mOrder, mLow;
    std::vector<char> mOnStack, mTainted;
    std::vector<int> mSccStack, mLevel;
    std::vector<std::pair<int, size_t>> mFrames;
    std::vector<OrderedDefinition> mOut;
    int mCounter = 0;
};

}  // namespace

std::vector<OrderedDefinition> definitionOrder(
    const std::map<std::string, const Statement*>& lets,
    const std::map<std::string, const Statement*>& solids, const DiagnosticSink& sink) {
    const std::vector<const Statement*> defs = definitionsInFileOrder(lets, solids, sink);
    std::unordered_map<const Statement*, int> index;
    for (size_t i = 0; i < defs.size(); ++i) index[defs[i]] = static_cast<int>(i);
    const int n = static_cast<int>(defs.size());
    std::vector<std::vector<Use>> uses(n);
    UseCollector collector(lets, solids, index);
    for (int i = 0; i < n; ++i) uses[i] = collector.collect(*defs[i]);
    return DependencyOrder(defs, uses).run();
}

}  // namespace kerf
