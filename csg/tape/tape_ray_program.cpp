// The interval method's ray-specialised evaluation of a tape: parts that are polynomials of
// degree <= 2 in t along the ray are folded into exact ranges once per ray
// (csg/tape/tape_ray_program.h).
#include "csg/tape/tape_ray_program.h"

#include <stdexcept>
#include "csg/tape/derivative_rules.h"
#include "csg/tape/tape_ray_step.h"

namespace kerf {

using namespace ray_step;

// ---------------------------------------------------------------------------------------------
// TapeRayProgram (csg/tape/tape_ray_program.h): the comparison method's evaluator. It shares the
// per-instruction arithmetic with Tape::evalIntervalAlongRay (csg/tape/tape_ray_step.h) and never
// changes what the default path runs.

namespace {

using Coefficients = TapeRayProgram::Coefficients;

/// x + y on coefficients, keeping exact zeros exact.
Interval coefSum(const Interval& x, const Interval& y) { return sum(x, y); }

/// x·y on coefficients, exactly 0 when either is.
Interval coefProduct(const Interval& x, const Interval& y) {
    if (isExactZero(x) || isExactZero(y)) return Interval(0.0, 0.0, x.maybeNan || y.maybeNan);
    return interval_kernel::mul(x, y);
}

int8_t degreeOf(const Interval* c) {
    for (int k = 2; k > 0; --k)
        if (!isExactZero(c[k])) return static_cast<int8_t>(k);
    return 0;
}

/// Whether op applied to operands with these flags computes a real function ≥ 0 wherever it is
/// defined.
bool nonNegativeResult(Op op, bool a, bool b, double value) {
    switch (op) {
        case Op::Const: return value >= 0.0;
        case Op::Square:
        case Op::Sqrt:
        case Op::Abs:
        case Op::Exp: return true;
        case Op::PowInt: return static_cast<int>(value) % 2 == 0 || a;
        case Op::Add:
        case Op::Mul:
        case Op::Div:
        case Op::Min: return a && b;
        case Op::Max: return a || b;
        default: return false;
    }
}

/// The coefficients of a square of a polynomial of degree ≤ 1.
void squareOf(const Coefficients& x, Coefficients& r) {
    r.c[0] = sqr(x.c[0]);
    const Interval cross = coefProduct(x.c[0], x.c[1]);
    r.c[1] = isExactZero(cross) ? cross : interval_kernel::scale(cross, 2.0, cross.maybeNan);
    r.c[2] = isExactZero(x.c[1]) ? x.c[1] : sqr(x.c[1]);
}

/// The degree an instruction has along a general ray when it is a polynomial of degree ≤ 2
/// whose coefficients the plan can fold; −1 otherwise. Division only by a constant that
/// cannot be 0.
int foldedDegree(const TapeInstr& in, int da, int db, const Interval& divisor) {
    switch (in.op) {
        case Op::Const: return 0;
        case Op::VarX:
        case Op::VarY:
        case Op::VarZ: return 1;
        default: break;
    }
    if (da < 0 || (in.b >= 0 && db < 0)) return -1;
    if (da == 0 && (in.b < 0 || db == 0)) return 0;  // constants only: folded by the plan
    switch (in.op) {
        case Op::Neg: return da;
        case Op::Add:
        case Op::Sub: return std::max(da, db);
        case Op::Mul: return da + db <= 2 ? da + db : -1;
        case Op::Square: return da <= 1 ? 2 * da : -1;
        case Op::PowInt: {
            const int n = static_cast<int>(in.value);
            return n == 0 ? 0 : n == 1 ? da : (n == 2 && da <= 1) ? 2 * da : -1;
        }
        case Op::Div: return db == 0 && !divisor.containsZero() && !divisor.maybeNan ? da : -1;
        default: return -1;
    }
}

/// The coefficients of polynomial part p from its operands' (the plan made sure it folds).
void foldCoefficients(const TapeRayPlan::Poly& p, const Coefficients* x, const Coefficients* y,
                      Coefficients& r) {
    for (Interval& c : r.c) c = Interval(0.0);
    switch (p.op) {
        case Op::Neg:
            for (int k = 0; k <= x->deg; ++k) r.c[k] = -x->c[k];
            break;
        case Op::Add:
        case Op::Sub:
            for (int k = 0; k < 3; ++k)
                r.c[k] = coefSum(x->c[k], p.op == Op::Add ? y->c[k] : -y->c[k]);
            break;
        case Op::Mul:
            for (int i = 0; i <= x->deg; ++i)
                for (int j = 0; j <= y->deg; ++j)
                    r.c[i + j] = coefSum(r.c[i + j], coefProduct(x->c[i], y->c[j]));
            break;
        case Op::Square: squareOf(*x, r); break;
        case Op::PowInt:  // n = 1 or 2 (n = 0 is a constant)
            if (static_cast<int>(p.value) == 1) {
                for (int k = 0; k < 3; ++k) r.c[k] = x->c[k];
            } else {
                squareOf(*x, r);
            }
            break;
        case Op::Div:
            for (int k = 0; k <= x->deg; ++k)
                r.c[k] = isExactZero(x->c[k]) ? x->c[k] : x->c[k] / y->c[0];
            break;
        default: break;  // the plan folds nothing else
    }
}

/// c0 + c1·x + c2·x² at a point, by Horner.
Interval hornerAt(const Coefficients& s, double x) {
    using namespace interval_kernel;
    const Interval inner = add(s.c[1], scale(s.c[2], x, s.c[2].maybeNan));
    return add(s.c[0], scale(inner, x, inner.maybeNan));
}

/// A polynomial part's range and slope over t.
void polynomialRange(Coefficients& s, const Interval& t, Interval& v, Interval& d) {
    using namespace interval_kernel;
    switch (s.deg) {
        case 0:
            v = s.c[0];
            d = Interval(0.0);
            return;
        case 1:
            v = add(s.c[0], mul(t, s.c[1]));
            d = s.c[1];
            return;
        default: break;
    }
    const Interval c2t = mul(t, s.c[2]);
    d = add(s.c[1], scale(c2t, 2.0, c2t.maybeNan));
    if (s.definite && std::isfinite(t.lo) && std::isfinite(t.hi)) {
        // Every quadratic with coefficients in c takes its extremes over [lo, hi] at the ends
        // or at its vertex, and its vertex lies in [lo, hi] only where its slope c1 + 2·c2·t
        // (enclosed by d) vanishes there.
        v = hull(hornerAt(s, t.lo), hornerAt(s, t.hi));
        if (d.containsZero() || d.maybeNan) {
            if (!s.extremumReady) {
                s.extremum = sub(s.c[0], sqr(s.c[1]) / scale(s.c[2], 4.0, false));
                s.extremumReady = true;
            }
            v = hull(v, s.extremum);
        }
        return;
    }
    v = add(add(s.c[0], mul(t, s.c[1])), mul(sqr(t), s.c[2]));
}

}  // namespace

bool TapeRayPlan::accepts(const Tape& tape) {
    for (const TapeInstr& in : tape.instrs())
        if (in.op == Op::Noise || in.op == Op::Field) return false;
    return true;
}

TapeRayPlan::TapeRayPlan(const Tape& tape) {
    const std::vector<TapeInstr>& instrs = tape.instrs();
    const size_t n = instrs.size();
    std::vector<int> degree(n), polyIndex(n, -1), stepIndex(n, -1);
    std::vector<char> nonNegative(n), needed(n, 0);
    std::vector<Interval> constant(n);
    for (size_t i = 0; i < n; ++i) {
        const TapeInstr& in = instrs[i];
        // Plans are made for the implicit forms of closed-form primitives, which hold no noise.
        if (in.op == Op::Noise) throw std::invalid_argument("TapeRayPlan: a tape with noise");
        if (in.op == Op::Field) throw std::invalid_argument("TapeRayPlan: a tape with a field");
        const int da = in.a >= 0 ? degree[in.a] : 0, db = in.b >= 0 ? degree[in.b] : 0;
        const Interval divisor = in.b >= 0 && db == 0 ? constant[in.b] : Interval(0.0);
        degree[i] = foldedDegree(in, da, db, divisor);
        nonNegative[i] = nonNegativeResult(in.op, in.a >= 0 && nonNegative[in.a],
                                           in.b >= 0 && nonNegative[in.b], in.value);
        if (degree[i] < 0) continue;
        Poly p{in.op, static_cast<int8_t>(degree[i]), -1, -1, in.value, Interval()};
        if (in.op == Op::Const) {
            p.constant = Interval(in.value);
        } else if (degree[i] == 0) {
            p.constant = applyIntervalOp(in.op, constant[in.a],
                                         in.b >= 0 ? constant[in.b] : Interval(), in.value);
        } else {
            p.a = in.a >= 0 ? polyIndex[in.a] : -1;
            p.b = in.b >= 0 ? polyIndex[in.b] : -1;
        }
        if (degree[i] == 0) p.op = Op::Const;
        constant[i] = p.constant;
        polyIndex[i] = static_cast<int>(mPolys.size());
        mPolys.push_back(p);
    }
    // Keep what the root needs: a polynomial part needs none of its operands.
    needed[n - 1] = 1;
    for (size_t i = n; i-- > 0;) {
        if (!needed[i] || degree[i] >= 0) continue;
        if (instrs[i].a >= 0) needed[instrs[i].a] = 1;
        if (instrs[i].b >= 0) needed[instrs[i].b] = 1;
    }
    for (size_t i = 0; i < n; ++i) {
        if (!needed[i]) continue;
        const TapeInstr& in = instrs[i];
        Step s{in.op, degree[i] >= 0, nonNegative[i] != 0, -1, -1, polyIndex[i], in.value};
        if (!s.poly) {
            s.a = in.a >= 0 ? stepIndex[in.a] : -1;
            s.b = in.b >= 0 ? stepIndex[in.b] : -1;
        }
        stepIndex[i] = static_cast<int>(mSteps.size());
        mSteps.push_back(s);
    }
}

void TapeRayProgram::prepare(const TapeRayPlan& plan, const Ray& ray) {
    mPlan = &plan;
    const std::vector<TapeRayPlan::Poly>& polys = plan.polys();
    mCoefficients.resize(polys.size());
    for (size_t i = 0; i < polys.size(); ++i) {
        const TapeRayPlan::Poly& p = polys[i];
        Coefficients& r = mCoefficients[i];
        switch (p.op) {
            case Op::Const:
                r.c[0] = p.constant;
                r.c[1] = r.c[2] = Interval(0.0);
                break;
            case Op::VarX:
            case Op::VarY:
            case Op::VarZ: {
                const int axis = static_cast<int>(p.op) - static_cast<int>(Op::VarX);
                r.c[0] = Interval(ray.origin[axis]);
                r.c[1] = Interval(ray.dir[axis]);
                r.c[2] = Interval(0.0);
                break;
            }
            default:
                foldCoefficients(p, &mCoefficients[p.a], p.b >= 0 ? &mCoefficients[p.b] : nullptr,
                                 r);
        }
        r.deg = degreeOf(r.c);
        for (int k = 0; k < 3; ++k) r.m[k] = r.c[k].lo == r.c[k].hi ? r.c[k].lo : r.c[k].mid();
        r.definite = r.deg == 2 && !r.c[2].maybeNan && (r.c[2].lo > 0.0 || r.c[2].hi < 0.0);
        r.extremumReady = false;
    }
}

void TapeRayProgram::eval(const Interval& t, Interval& f, Interval& dfdt) {
    thread_local std::vector<RaySlot> slots;
    const std::vector<TapeRayPlan::Step>& steps = mPlan->steps();
    const size_t n = steps.size();
    if (slots.size() < n) slots.resize(n);
    RaySlot* s = slots.data();
    for (size_t i = 0; i < n; ++i) {
        const TapeRayPlan::Step& in = steps[i];
        RaySlot& r = s[i];
        r.hasTrig = false;
        if (in.poly) {
            polynomialRange(mCoefficients[in.source], t, r.v, r.d);
        } else {
            switch (in.op) {
                default: evalStep(in.op, in.a, in.b, in.value, s, r);
            }
        }
        // A function that cannot be negative: rounding below 0 is only rounding. Not where a
        // NaN may come out: min and max pass their other operand on for it, so the enclosure
        // must stay as the plain evaluator makes it.
        if (in.nonNegative && !r.v.maybeNan && r.v.lo < 0.0 && r.v.hi >= 0.0) r.v.lo = 0.0;
        r.zeroSlope = isExactZero(r.d);
    }
    f = s[n - 1].v;
    dfdt = s[n - 1].d;
}

double TapeRayProgram::valueAndSlope(double t, double& dfdt) {
    struct Point {
        double v, d;
    };
    thread_local std::vector<Point> slots;
    const std::vector<TapeRayPlan::Step>& steps = mPlan->steps();
    const size_t n = steps.size();
    if (slots.size() < n) slots.resize(n);
    Point* s = slots.data();
    for (size_t i = 0; i < n; ++i) {
        const TapeRayPlan::Step& in = steps[i];
        if (in.poly) {
            const double* m = mCoefficients[in.source].m;
            s[i] = {m[0] + t * (m[1] + t * m[2]), m[1] + 2.0 * m[2] * t};
        } else {
            const Point a = s[in.a];
            const Point b = in.b >= 0 ? s[in.b] : Point{0.0, 0.0};
            const double v = applyScalarOp(in.op, a.v, b.v, in.value);
            s[i] = {v, derivative_rules::derivative(in.op, a.v, a.d, b.v, b.d, in.value, v)};
        }
    }
    dfdt = s[n - 1].d;
    return s[n - 1].v;
}

}  // namespace kerf
