// Tape compilation: the nodes the root depends on, in evaluation order, renumbered densely.
// The evaluators live in tape_eval_*.cpp, one per kind of value.
#include "csg/tape/tape.h"

#include "csg/tape/scalar_field.h"

namespace kerf {

std::shared_ptr<const Tape> Tape::compile(const ExprGraph& graph, ExprId root) {
    const std::vector<ExprNode>& nodes = graph.nodes();
    // Operands always precede their users in the graph, so one backward sweep marks every
    // node the root needs, and one forward sweep emits them in a valid order.
    std::vector<char> needed(nodes.size(), 0);
    needed[root] = 1;
    for (ExprId i = root; i >= 0; --i) {
        if (!needed[i]) continue;
        if (nodes[i].a >= 0) needed[nodes[i].a] = 1;
        if (nodes[i].b >= 0) needed[nodes[i].b] = 1;
        if (nodes[i].c >= 0) needed[nodes[i].c] = 1;
    }
    std::vector<int32_t> slotOf(nodes.size(), -1);
    // The graph's field index -> the tape's: only fields the tape calls are copied.
    std::vector<int32_t> fieldOf(graph.fields().size(), -1);
    auto tape = std::make_shared<Tape>();
    for (ExprId i = 0; i <= root; ++i) {
        if (!needed[i]) continue;
        const ExprNode& n = nodes[i];
        double value = n.value;
        if (n.op == Op::Field) {
            const size_t g = static_cast<size_t>(n.value);
            if (fieldOf[g] < 0) {
                fieldOf[g] = static_cast<int32_t>(tape->mFields.size());
                tape->mFields.push_back(graph.fields()[g]);
            }
            value = fieldOf[g];
        }
        slotOf[i] = static_cast<int32_t>(tape->mInstrs.size());
        tape->mInstrs.push_back({n.op, n.a >= 0 ? slotOf[n.a] : -1, n.b >= 0 ? slotOf[n.b] : -1,
                                 n.c >= 0 ? slotOf[n.c] : -1, value});
    }
    tape->finish();
    return tape;
}

Interval lipschitzPartial(const ScalarField& field) {
    const double L = field.lipschitz();
    return L >= 0.0 && L < kInf ? Interval(-L, L) : Interval::entire();
}

void Tape::finish() {
    mLeanAlongRay = true;
    for (const TapeInstr& in : mInstrs) switch (in.op) {
            case Op::Const:  // a NaN constant is flagged (Interval(NaN)): the lean path keeps none
                if (std::isnan(in.value)) mLeanAlongRay = false;
                break;
            case Op::VarX:
            case Op::VarY:
            case Op::VarZ:
            case Op::Add:
            case Op::Sub:
            case Op::Mul:
            case Op::Neg:
            case Op::Square:
            case Op::Sin:
            case Op::Cos: break;
            default: mLeanAlongRay = false;
        }
}

}  // namespace kerf
