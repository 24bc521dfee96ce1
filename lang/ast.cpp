// A statement's nodes moved from the parser's scratch arena into one exact-size block of its
// own, so lowering can free each statement's tree once it is lowered.
#include "lang/ast.h"

#include <stdexcept>

namespace kerf {

static_assert(sizeof(Expr) % 8 == 0 && sizeof(Solid) % 8 == 0 && sizeof(Property) % 8 == 0 &&
                  sizeof(Modifier) % 8 == 0,
              "node sizes are multiples of 8, so the scratch arena's count bounds the copy");
static_assert(alignof(Expr) <= 8 && alignof(Solid) <= 8 && alignof(Property) <= 8 &&
              alignof(Modifier) <= 8);

/// Deep copy of a statement's nodes into one block, each list again side by side.
class TreeCopier {
public:
    TreeCopier(std::byte* out, size_t capacity) : mOut(out), mCapacity(capacity) {}

    const Expr* one(const Expr* e) { return e ? list(ExprList(e, 1)).begin() : nullptr; }
    const Solid* one(const Solid* s) { return s ? list(ArenaList<Solid>(s, 1)).begin() : nullptr; }

    template <class T>
    ArenaList<T> list(const ArenaList<T>& src) {
        if (src.empty()) return {};
        T* dst = take<T>(src.size());
        for (size_t i = 0; i < src.size(); ++i) {
            dst[i] = src[i];
            fix(dst[i]);
        }
        return ArenaList<T>(dst, static_cast<uint32_t>(src.size()));
    }

private:
    void fix(Expr& e) {
        if (e.kind == Expr::Kind::SolidValue) e.solid = one(e.solid);
        const ExprList args = e.args();
        if (!args.empty()) e.first = list(args).begin();
    }
    void fix(Property& p) {
        p.expr = one(p.expr);
        p.solid = one(p.solid);
    }
    void fix(Modifier& m) {
        m.args = list(m.args);
        m.pattern = one(m.pattern);
    }
    void fix(Solid& s) {
        s.properties = list(s.properties);
        s.children = list(s.children);
        s.modifiers = list(s.modifiers);
    }

    template <class T>
    T* take(size_t n) {
        const size_t bytes = n * sizeof(T);
        if (mUsed + bytes > mCapacity)
            throw std::logic_error("Statement::takeTree: bound too small");
        T* p = reinterpret_cast<T*>(mOut + mUsed);
        mUsed += bytes;
        return p;
    }

    std::byte* mOut;
    size_t mCapacity;
    size_t mUsed = 0;
};

void Statement::moveTreeWith(TreeCopier& copier) {
    expr = copier.one(expr);
    solid = copier.one(solid);
    properties = copier.list(properties);
    if (!block) return;
    for (Statement& s : block->body) s.moveTreeWith(copier);
    for (Statement& s : block->elseBody) s.moveTreeWith(copier);
}

void Statement::takeTree(size_t bound) {
    if (bound == 0 || (!expr && !solid && properties.empty() && !block)) {
        releaseTree();
        return;
    }
    const size_t words = (bound + sizeof(std::max_align_t) - 1) / sizeof(std::max_align_t);
    std::unique_ptr<std::max_align_t[]> memory(new std::max_align_t[words]);
    TreeCopier copier(reinterpret_cast<std::byte*>(memory.get()), words * sizeof(std::max_align_t));
    moveTreeWith(copier);
    tree = std::move(memory);
}

void Statement::releaseTree() {
    expr = nullptr;
    solid = nullptr;
    properties = {};
    block.reset();
    tree.reset();
}

}  // namespace kerf
