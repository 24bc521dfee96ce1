// The section tape and its interval slopes.
#include "slice/section_tape.h"

#include "csg/interval/interval_ops.h"
#include "csg/tape/derivative_rules.h"
#include "csg/tape/noise.h"
#include "csg/tape/scalar_field.h"
#include "csg/tape/tree_tape.h"

namespace kerf {

namespace {

/// c + a·u + b·v + d·w with the zero terms left out, so an axis plane costs nothing.
ExprId affineOf(ExprGraph& g, double c, double a, double b, double d) {
    ExprId sum = -1;
    auto add = [&](ExprId term) { sum = sum < 0 ? term : g.binary(Op::Add, sum, term); };
    const ExprId vars[3] = {g.x(), g.y(), g.z()};
    const double k[3] = {a, b, d};
    for (int i = 0; i < 3; ++i) {
        if (k[i] == 0.0) continue;
        add(k[i] == 1.0 ? vars[i] : g.binary(Op::Mul, g.constant(k[i]), vars[i]));
    }
    if (c != 0.0 || sum < 0) add(g.constant(c));
    return sum;
}

}  // namespace

std::shared_ptr<const Tape> sectionTape(const Node& node, const SlicePlane& plane) {
    ExprGraph g;
    ExprId xyz[3];
    for (int i = 0; i < 3; ++i)
        xyz[i] = affineOf(g, plane.origin[i], plane.u[i], plane.v[i], plane.normal[i]);
    return Tape::compile(g, treeExpr(node, g, xyz[0], xyz[1], xyz[2]));
}

namespace {

/// Whether the section's slopes have a rule for op: those ops whose derivative enclosure over a
/// cell stays finite where the op is defined; the others (tan, asin, acos, atan2, pow, floor,
/// ceil) leave nothing to conclude.
bool hasSectionRule(Op op) {
    switch (op) {
        case Op::Tan:
        case Op::Asin:
        case Op::Acos:
        case Op::Atan2:
        case Op::Pow:
        case Op::Floor:
        case Op::Ceil: return false;
        default: return true;
    }
}

/// The inputs: constants, u, v (varying) and w (fixed); r[0] the value, r[1] d/du, r[2] d/dv.
void inputSlot(const TapeInstr& in, const Interval& u, const Interval& v, double w, Interval* r) {
    const Interval zero(0.0), one(1.0);
    r[1] = r[2] = zero;
    switch (in.op) {
        case Op::Const: r[0] = in.value; break;
        case Op::VarX:
            r[0] = u;
            r[1] = one;
            break;
        case Op::VarY:
            r[0] = v;
            r[2] = one;
            break;
        default: r[0] = w;  // Op::VarZ
    }
}

/// Noise and fields: the value and the chain rule through the gradient enclosure over the box.
void ternarySlot(const Tape& tape, const TapeInstr& in, const Interval* a, const Interval* b,
                 const Interval* c, Interval* r) {
    Interval g[3];
    r[0] = in.op == Op::Noise ? gradientNoiseRange(a[0], b[0], c[0], noiseSeed(in), g)
                              : tape.field(in).rangeGradient(a[0], b[0], c[0], g);
    for (int k = 1; k < 3; ++k) r[k] = derivative_rules::chainSlope(g, a[k], b[k], c[k]);
}

/// Any other op: its value, then the shared derivative rule once per direction (sin and cos
/// from one reduction).
void opSlot(const TapeInstr& in, const Interval* a, const Interval* b, Interval* r) {
    using namespace derivative_rules;
    if (in.op == Op::Sin || in.op == Op::Cos) {
        Interval sn, cs;
        sinCos(a[0], sn, cs);
        r[0] = in.op == Op::Sin ? sn : cs;
        for (int k = 1; k < 3; ++k)
            r[k] = in.op == Op::Sin ? sinSlope(cs, a[k]) : cosSlope(sn, a[k]);
        return;
    }
    const Interval none;
    r[0] = applyIntervalOp(in.op, a[0], b ? b[0] : none, in.value);
    for (int k = 1; k < 3; ++k)
        r[k] = derivative(in.op, a[0], a[k], b ? b[0] : none, b ? b[k] : none, in.value, r[0]);
}

}  // namespace

IntervalSlopes evalIntervalSlopes(const Tape& tape, const Interval& u, const Interval& v, double w,
                                  std::vector<Interval>& s) {
    const auto& ins = tape.instrs();
    const size_t n = ins.size();
    s.resize(3 * n);  // value, d/du, d/dv per slot
    IntervalSlopes out;
    for (size_t i = 0; i < n; ++i) {
        const TapeInstr& in = ins[i];
        Interval* r = &s[3 * i];
        const Interval* a = in.a >= 0 ? &s[3 * in.a] : nullptr;
        const Interval* b = in.b >= 0 ? &s[3 * in.b] : nullptr;
        if (!hasSectionRule(in.op)) return out;  // no rule, no conclusion
        if (in.a < 0) {
            inputSlot(in, u, v, w, r);
        } else if (in.op == Op::Noise || in.op == Op::Field) {
            ternarySlot(tape, in, a, b, &s[3 * in.c], r);
        } else {
            opSlot(in, a, b, r);
        }
        for (int k = 0; k < 3; ++k)
            if (r[k].maybeNan) return out;
    }
    out.f = s[3 * (n - 1)];
    out.du = s[3 * (n - 1) + 1];
    out.dv = s[3 * (n - 1) + 2];
    out.ok = true;
    return out;
}

}  // namespace kerf
