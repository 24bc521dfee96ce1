// Tape simplification over a region: interval evaluation records which operand decided each
// min/max (and abs, whose sign decides it), then a shorter tape keeps only the chosen branches
// (libfive's Tape::push, Fidget's simplify). Within the region the shorter tape gives the same
// doubles: a decided min(a, b) has a < b at every point of the region (point values lie in
// their intervals), so it is a; abs(a) with a > 0 throughout is a, with a < 0 it is −a.
#include "csg/interval/interval_ops.h"
#include "csg/tape/noise.h"
#include "csg/tape/scalar_field.h"
#include "csg/tape/tape.h"

namespace kerf {
namespace {

/// Which operand of op(a, b) (min or max) gives its value wherever a ∈ A, b ∈ B; Both if undecided.
/// An interval that may hold NaN decides nothing (min and max treat NaN asymmetrically).
Choice choose(Op op, const Interval& a, const Interval& b) {
    if (a.maybeNan || b.maybeNan) return Choice::Both;
    if (op == Op::Min) {
        if (a.hi < b.lo) return Choice::Left;
        if (b.hi < a.lo) return Choice::Right;
    } else {
        if (a.lo > b.hi) return Choice::Left;
        if (b.lo > a.hi) return Choice::Right;
    }
    // Strict comparisons: where A and B touch, a tie (or ±0) could pick either operand's bits.
    return Choice::Both;
}

}  // namespace

Interval Tape::evalInterval(const Interval& x, const Interval& y, const Interval& z,
                            std::vector<Choice>& choices) const {
    thread_local std::vector<Interval> slots;
    slots.resize(mInstrs.size());
    choices.assign(mInstrs.size(), Choice::Both);
    Interval* s = slots.data();
    for (size_t i = 0; i < mInstrs.size(); ++i) {
        const TapeInstr& in = mInstrs[i];
        switch (in.op) {
            case Op::Const: s[i] = Interval(in.value); break;
            case Op::VarX: s[i] = x; break;
            case Op::VarY: s[i] = y; break;
            case Op::VarZ: s[i] = z; break;
            case Op::Min:
            case Op::Max: {
                const Choice c = choose(in.op, s[in.a], s[in.b]);
                choices[i] = c;
                s[i] = c == Choice::Left    ? s[in.a]
                       : c == Choice::Right ? s[in.b]
                                            : applyIntervalOp(in.op, s[in.a], s[in.b], in.value);
                break;
            }
            case Op::Abs: {
                // abs of a one-signed operand is the operand (Left) or its negation (Right).
                const Interval& a = s[in.a];
                if (!a.maybeNan && a.lo > 0.0) choices[i] = Choice::Left;
                if (!a.maybeNan && a.hi < 0.0) choices[i] = Choice::Right;
                s[i] = applyIntervalOp(in.op, a, Interval(), in.value);
                break;
            }
            case Op::Add:
                s[i] = applyIntervalOp(in.op, s[in.a], s[in.b], in.value);
                // A sum of non-negative terms (squares) stays so: see nonNegative().
                if (s[in.a].lo >= 0.0 && s[in.b].lo >= 0.0) s[i] = nonNegative(s[i]);
                break;
            case Op::Noise:
                s[i] = gradientNoiseRange(s[in.a], s[in.b], s[in.c], noiseSeed(in));
                break;
            case Op::Field: s[i] = field(in).range(s[in.a], s[in.b], s[in.c]); break;
            default:
                s[i] = applyIntervalOp(in.op, s[in.a], in.b >= 0 ? s[in.b] : Interval(), in.value);
        }
    }
    return s[mInstrs.size() - 1];
}

std::shared_ptr<const Tape> Tape::simplified(const std::vector<Choice>& choices) const {
    const int n = size();
    // alias[i]: the slot whose value instruction i computes (itself unless it is a decided
    // min/max, which computes its chosen operand's).
    std::vector<int32_t> alias(n);
    for (int i = 0; i < n; ++i) {
        const TapeInstr& in = mInstrs[i];
        alias[i] = i;
        if (in.op == Op::Abs && choices[i] == Choice::Left) alias[i] = alias[in.a];
        if (in.op != Op::Min && in.op != Op::Max) continue;
        if (choices[i] == Choice::Left) alias[i] = alias[in.a];
        if (choices[i] == Choice::Right) alias[i] = alias[in.b];
    }
    // Instructions the root still needs, through the aliases; operands precede their users.
    std::vector<char> needed(n, 0);
    const int root = alias[n - 1];
    needed[root] = 1;
    for (int i = root; i >= 0; --i) {
        if (!needed[i]) continue;
        if (mInstrs[i].a >= 0) needed[alias[mInstrs[i].a]] = 1;
        if (mInstrs[i].b >= 0) needed[alias[mInstrs[i].b]] = 1;
        if (mInstrs[i].c >= 0) needed[alias[mInstrs[i].c]] = 1;
    }
    std::vector<int32_t> slotOf(n, -1);
    auto tape = std::make_shared<Tape>();
    tape->mFields = mFields;  // Field instructions keep their indices
    for (int i = 0; i <= root; ++i) {
        if (!needed[i]) continue;
        TapeInstr in = mInstrs[i];
        if (in.op == Op::Abs && choices[i] == Choice::Right) in.op = Op::Neg;  // −a = |a| exactly
        if (in.a >= 0) in.a = slotOf[alias[in.a]];
        if (in.b >= 0) in.b = slotOf[alias[in.b]];
        if (in.c >= 0) in.c = slotOf[alias[in.c]];
        slotOf[i] = static_cast<int32_t>(tape->mInstrs.size());
        tape->mInstrs.push_back(in);
    }
    tape->finish();
    return tape;
}

}  // namespace kerf
