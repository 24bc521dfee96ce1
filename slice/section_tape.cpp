// The section tape and its interval slopes.
#include "slice/section_tape.h"

#include "csg/interval/interval_ops.h"
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

IntervalSlopes evalIntervalSlopes(const Tape& tape, const Interval& u, const Interval& v, double w,
                                  std::vector<Interval>& s) {
    const auto& ins = tape.instrs();
    const size_t n = ins.size();
    s.resize(3 * n);  // value, d/du, d/dv per slot
    const Interval zero(0.0), one(1.0);
    IntervalSlopes out;
    for (size_t i = 0; i < n; ++i) {
        const TapeInstr& in = ins[i];
        Interval* r = &s[3 * i];
        const Interval* a = in.a >= 0 ? &s[3 * in.a] : nullptr;
        const Interval* b = in.b >= 0 ? &s[3 * in.b] : nullptr;
        switch (in.op) {
            case Op::Const:
                r[0] = in.value;
                r[1] = r[2] = zero;
                break;
            case Op::VarX:
                r[0] = u;
                r[1] = one;
                r[2] = zero;
                break;
            case Op::VarY:
                r[0] = v;
                r[1] = zero;
                r[2] = one;
                break;
            case Op::VarZ:
                r[0] = w;
                r[1] = r[2] = zero;
                break;
            case Op::Neg:
                for (int k = 0; k < 3; ++k) r[k] = -a[k];
                break;
            case Op::Add:
                for (int k = 0; k < 3; ++k) r[k] = a[k] + b[k];
                break;
            case Op::Sub:
                for (int k = 0; k < 3; ++k) r[k] = a[k] - b[k];
                break;
            case Op::Mul:
                r[0] = a[0] * b[0];
                for (int k = 1; k < 3; ++k) r[k] = a[k] * b[0] + a[0] * b[k];
                break;
            case Op::Div: {
                r[0] = a[0] / b[0];
                for (int k = 1; k < 3; ++k) r[k] = (a[k] - r[0] * b[k]) / b[0];
                break;
            }
            case Op::Square:
                r[0] = sqr(a[0]);
                for (int k = 1; k < 3; ++k) r[k] = Interval(2.0) * a[0] * a[k];
                break;
            case Op::Sqrt: {
                r[0] = sqrt(a[0]);
                const Interval twice = Interval(2.0) * r[0];
                for (int k = 1; k < 3; ++k) r[k] = a[k] / twice;  // NaN-flagged where r holds 0
                break;
            }
            case Op::PowInt: {
                const int p = static_cast<int>(in.value);
                r[0] = powInt(a[0], p);
                const Interval d = Interval(double(p)) * powInt(a[0], p - 1);
                for (int k = 1; k < 3; ++k) r[k] = d * a[k];
                break;
            }
            case Op::Sin:
            case Op::Cos: {
                Interval sn, cs;
                sinCos(a[0], sn, cs);
                r[0] = in.op == Op::Sin ? sn : cs;
                const Interval d = in.op == Op::Sin ? cs : -sn;
                for (int k = 1; k < 3; ++k) r[k] = d * a[k];
                break;
            }
            case Op::Exp:
                r[0] = exp(a[0]);
                for (int k = 1; k < 3; ++k) r[k] = r[0] * a[k];
                break;
            case Op::Log:
                r[0] = log(a[0]);
                for (int k = 1; k < 3; ++k) r[k] = a[k] / a[0];
                break;
            case Op::Atan:
                r[0] = atan(a[0]);
                for (int k = 1; k < 3; ++k) r[k] = a[k] / (Interval(1.0) + sqr(a[0]));
                break;
            case Op::Abs:
                r[0] = abs(a[0]);
                for (int k = 1; k < 3; ++k)
                    r[k] = a[0].lo > 0.0 ? a[k] : a[0].hi < 0.0 ? -a[k] : hull(a[k], -a[k]);
                break;
            case Op::Min:
            case Op::Max: {
                const bool isMin = in.op == Op::Min;
                r[0] = isMin ? min(a[0], b[0]) : max(a[0], b[0]);
                // Which operand is the result over the whole box, if one is.
                const bool aWins = isMin ? a[0].hi < b[0].lo : a[0].lo > b[0].hi;
                const bool bWins = isMin ? b[0].hi < a[0].lo : b[0].lo > a[0].hi;
                for (int k = 1; k < 3; ++k) r[k] = aWins ? a[k] : bWins ? b[k] : hull(a[k], b[k]);
                break;
            }
            case Op::Noise: {  // the chain rule through the noise's gradient enclosure
                const Interval* c = &s[3 * in.c];
                Interval g[3];
                r[0] = gradientNoiseRange(a[0], b[0], c[0], noiseSeed(in), g);
                for (int k = 1; k < 3; ++k) r[k] = g[0] * a[k] + g[1] * b[k] + g[2] * c[k];
                break;
            }
            case Op::Field: {  // the chain rule through the field's gradient enclosure
                const Interval* c = &s[3 * in.c];
                Interval g[3];
                r[0] = tape.field(in).rangeGradient(a[0], b[0], c[0], g);
                for (int k = 1; k < 3; ++k) r[k] = g[0] * a[k] + g[1] * b[k] + g[2] * c[k];
                break;
            }
            default:
                return out;  // tan, asin, acos, atan2, pow, floor, ceil: no rule, no conclusion
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
