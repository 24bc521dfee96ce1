// Expression graph construction: hash-consing (equal nodes share one id) and folding of
// operations whose operands are all constants.
#include "csg/tape/expr.h"

#include <cstring>
#include <stdexcept>
#include <utility>

#include "csg/interval/interval_trig.h"
#include "csg/interval/scalar_ops.h"
#include "csg/tape/noise.h"
#include "csg/tape/scalar_field.h"

namespace kerf {
namespace {

uint64_t bitsOf(double v) {
    uint64_t b;
    std::memcpy(&b, &v, sizeof b);
    return b;
}

uint64_t mix(uint64_t h, uint64_t v) {
    // boost::hash_combine's recipe, widened to 64 bits.
    return h ^ (v + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2));
}

uint64_t hashOf(const ExprNode& n) {
    uint64_t h = static_cast<uint64_t>(n.op);
    h = mix(h, static_cast<uint32_t>(n.a));
    h = mix(h, static_cast<uint32_t>(n.b));
    h = mix(h, static_cast<uint32_t>(n.c));
    return mix(h, bitsOf(n.value));
}

/// Constants compare by bits, so 0 and −0 stay distinct (1/x tells them apart).
bool sameNode(const ExprNode& p, const ExprNode& q) {
    return p.op == q.op && p.a == q.a && p.b == q.b && p.c == q.c &&
           bitsOf(p.value) == bitsOf(q.value);
}

}  // namespace

ExprId ExprGraph::intern(const ExprNode& n) {
    std::vector<ExprId>& bucket = mIndex[hashOf(n)];
    for (ExprId id : bucket)
        if (sameNode(mNodes[id], n)) return id;
    const ExprId id = static_cast<ExprId>(mNodes.size());
    mNodes.push_back(n);
    bucket.push_back(id);
    return id;
}

ExprId ExprGraph::constant(double v) { return intern({Op::Const, -1, -1, -1, v}); }
ExprId ExprGraph::x() { return intern({Op::VarX, -1, -1, -1, 0.0}); }
ExprId ExprGraph::y() { return intern({Op::VarY, -1, -1, -1, 0.0}); }
ExprId ExprGraph::z() { return intern({Op::VarZ, -1, -1, -1, 0.0}); }

ExprId ExprGraph::unary(Op op, ExprId a) {
    // Folding uses the point evaluator's own arithmetic, so the folded tape evaluates to
    // the same doubles as the unfolded one would (sin and cos as Tape::eval computes them).
    if (mNodes[a].op == Op::Const) {
        if (op == Op::Sin || op == Op::Cos) {
            double s, c;
            interval_trig::pointSinCos(mNodes[a].value, s, c);
            return constant(op == Op::Sin ? s : c);
        }
        return constant(applyScalarOp(op, mNodes[a].value, 0.0, 0.0));
    }
    return intern({op, a, -1, -1, 0.0});
}

ExprId ExprGraph::binary(Op op, ExprId a, ExprId b) {
    if (mNodes[a].op == Op::Const && mNodes[b].op == Op::Const)
        return constant(applyScalarOp(op, mNodes[a].value, mNodes[b].value, 0.0));
    if (isCommutative(op) && a > b) std::swap(a, b);
    return intern({op, a, b, -1, 0.0});
}

ExprId ExprGraph::powInt(ExprId a, int n) {
    const double exponent = static_cast<double>(n);
    if (mNodes[a].op == Op::Const)
        return constant(applyScalarOp(Op::PowInt, mNodes[a].value, 0.0, exponent));
    // a¹ and a² need no power: a² as a square is one rounded product (what pow gives for an
    // exponent of 2) and takes every evaluator's fast path.
    if (n == 1) return a;
    if (n == 2) return unary(Op::Square, a);
    return intern({Op::PowInt, a, -1, -1, exponent});
}

ExprId ExprGraph::noise(ExprId x, ExprId y, ExprId z, uint64_t seed) {
    const double s = static_cast<double>(seed);
    const ExprNode &nx = mNodes[x], &ny = mNodes[y], &nz = mNodes[z];
    if (nx.op == Op::Const && ny.op == Op::Const && nz.op == Op::Const)
        return constant(gradientNoise(Vec3(nx.value, ny.value, nz.value), seed));
    return intern({Op::Noise, x, y, z, s});
}

ExprId ExprGraph::field(ExprId x, ExprId y, ExprId z, std::shared_ptr<const ScalarField> field) {
    if (!field) throw std::invalid_argument("ExprGraph::field: no field");
    // The table index tells fields apart in the hash-consing; graphs hold few fields, so a
    // linear search is enough. Never folded, even at a constant point: the extended
    // evaluator must still reach the field's own valueExtended.
    size_t index = 0;
    while (index < mFields.size() && mFields[index] != field) ++index;
    if (index == mFields.size()) mFields.push_back(std::move(field));
    return intern({Op::Field, x, y, z, static_cast<double>(index)});
}

}  // namespace kerf
