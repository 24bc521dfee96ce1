// Lowering, part 3c: `displace PATTERN by D`. The solid {f ≤ 0} becomes the implicit solid
// {f − D·h ≤ 0}, h the pattern's value mapped to [−1, 1], written into one expression with the
// solid's own implicit form (csg/tape/tree_tape.h), so that tracing, the octree, shadows and CSG
// all see the displaced surface through the same interval machinery as any implicit: the
// noise's enclosures (csg/tape/noise.h) keep root isolation from ever stepping over it.
#include "lang/lower.h"

#include "csg/primitives/clear_bound.h"
#include "csg/primitives/implicit_expr.h"
#include "csg/tape/tree_tape.h"
#include "csg/tree/solids.h"

#include <cmath>
#include <variant>

namespace kerf {
namespace {

/// The pattern's own value (its weight of b, as render/pattern_eval.cpp computes it without
/// filtering) at the pattern-space point q, mapped from [0, 1] to h in [−1, 1]. Only the
/// continuous patterns: a jump (a checker's cell wall) lying along a ray keeps every interval
/// over it ambiguous, and root isolation would split the whole ray down to the tolerance.
ExprId heightExpr(const Pattern& pattern, ExprBuilder& e, const ExprId q[3]) {
    ExprGraph& g = e.g;
    const auto fromWeight = [&](ExprId v) { return e.sub(e.mul(e.c(2.0), v), e.c(1.0)); };
    switch (pattern.kind) {
        case Pattern::Kind::Noise: return g.noise(q[0], q[1], q[2], pattern.seed);
        case Pattern::Kind::Turbulence: {
            // Σ |noise(2ᵒ·q)| / 2ᵒ over the octaves, normalised to [0, 1].
            ExprId sum = -1;
            double norm = 0.0, scale = 1.0;
            for (int o = 0; o < std::max(1, pattern.octaves); ++o, scale *= 2.0) {
                const ExprId n = g.noise(e.mul(q[0], e.c(scale)), e.mul(q[1], e.c(scale)),
                                         e.mul(q[2], e.c(scale)), pattern.seed + uint64_t(o));
                const ExprId term = e.mul(g.unary(Op::Abs, n), e.c(1.0 / scale));
                sum = sum < 0 ? term : e.add(sum, term);
                norm += 1.0 / scale;
            }
            return fromWeight(e.mul(sum, e.c(1.0 / norm)));
        }
        default: return -1;
    }
}

bool hasMotion(const Node& node) {
    if (node.kind() == NodeKind::Motion) return true;
    for (const NodePtr& child : node.children())
        if (hasMotion(*child)) return true;
    return false;
}

/// Evaluations a bound's proof may spend per try, and how many times the margin may double.
constexpr int kBoundBudget = 20000;
constexpr int kBoundDoublings = 24;

}  // namespace

NodePtr Lowering::displaced(const NodePtr& node, const Modifier& m) {
    const std::shared_ptr<const Pattern> pattern = lowerPattern(*m.pattern);
    const auto depthValue = evaluate(m.args[0], nullptr);
    if (!pattern || !depthValue) return nullptr;
    if (pattern->kind != Pattern::Kind::Noise && pattern->kind != Pattern::Kind::Turbulence) {
        error(m.pattern->loc, "displace takes a continuous pattern: noise or turbulence",
              "the steps of '" + m.pattern->name + "' would make walls no ray could resolve");
        return nullptr;
    }
    if (depthValue->type != Value::Type::Number || !std::isfinite(depthValue->number)) {
        error(m.args[0].start,
              "the displacement's depth must be a finite number, got " +
                  (depthValue->type == Value::Type::Number ? formatNumber(depthValue->number)
                                                           : typeName(depthValue->type)));
        return nullptr;
    }
    const double depth = depthValue->number;
    if (depth == 0.0) return node;
    if (hasMotion(*node)) {
        error(m.loc, "a moving solid cannot be displaced", "write displace before move and spin");
        return nullptr;
    }
    const Bounds3 inner = node->bounds();
    if (!inner.finite()) {
        error(m.loc, "only a bounded solid can be displaced", "intersect it with a box first");
        return nullptr;
    }
    ExprGraph graph;
    ExprBuilder e{graph};
    const ExprId x = graph.x(), y = graph.y(), z = graph.z();
    ExprId q[3];
    e.mapPoint(pattern->toPattern, x, y, z, q);
    const ExprId f =
        e.sub(treeExpr(*node, graph, x, y, z), e.mul(e.c(depth), heightExpr(*pattern, e, q)));
    const std::shared_ptr<const Tape> tape = Tape::compile(graph, f);
    // The surface can leave the solid's bounds by |D| where f grows like a distance, more where
    // it grows slower (a scaled solid): the bound grows until its faces are proved clear.
    const double pad = std::fabs(depth) * 1.25 + 1e-9 * glm::length(inner.extent());
    const auto bound = grownClearBound(*tape, inner, pad, kBoundDoublings, kBoundBudget);
    if (!bound) {
        error(
            m.loc,
            "cannot bound the displaced solid: its implicit form does not grow away from the solid",
            "displace a solid whose implicit form grows with distance (primitives do), or a "
            "smaller depth");
        return nullptr;
    }
    NodePtr out = makeImplicit(tape, *bound);
    // The solid keeps the material around it (the displaced solid is one primitive).
    if (node->kind() == NodeKind::Material)
        out = makeMaterial(out, std::get<MaterialParams>(node->params()).material);
    return out;
}

}  // namespace kerf
