/// @file csg/tape/tape_ray_program.h
/// @brief A tape specialised to one ray for interval evaluation along it: the same contract as
/// Tape::evalIntervalAlongRay (enclosures of f and df/dt over a t-interval), but much tighter
/// on the shapes closed-form primitives are made of, and cheaper per call. Used only by the
/// comparison-only interval method (csg/primitives/comparison_methods.h); the default path (tori,
/// implicits) keeps Tape::evalIntervalAlongRay, bit for bit.
///
/// Along a fixed ray p(t) = o + t·d every axis is affine in t, so every part of the tape built
/// from axes and constants by +, −, ×, negation, squares and division by a constant is a
/// polynomial in t. The plan (once per tape) finds the parts that are polynomials of degree
/// ≤ 2 and keeps only the instructions the remaining operations need; prepare() computes, once
/// per ray, their coefficients (as intervals, so they hold the exact real ones). eval() then
/// gets each such part's range
/// exactly, up to rounding: a quadratic's range over [a, b] is the hull of its values at a, b
/// and at its vertex, where the natural interval extension of (x−cx)²+(y−cy)²+(z−cz)² with
/// affine x, y, z overestimates badly near the minimum (the dependency problem). Its slope
/// c1 + 2·c2·t is exact too, so "0 ∉ df/dt" holds wherever the vertex is outside [a, b].
/// Generic: any expression of that shape benefits, whatever primitive wrote it.
///
/// It also knows which slots cannot be negative as real functions (squares, even powers,
/// sqrt, abs, exp, and sums, products and quotients of those), and clamps their enclosures'
/// lower ends at 0, so outward rounding of a sum of squares touching 0 never makes sqrt report
/// a possible NaN.
#pragma once

#include <vector>

#include "csg/interval/interval.h"
#include "csg/tape/expr.h"
#include "csg/tape/tape.h"
#include "csg/types.h"

namespace kerf {

/// What of a tape can be folded along any ray, worked out once per tape: which instructions
/// are polynomials of degree ≤ 2 in t (built from axes and constants by +, −, ×, negation,
/// squares, integer powers 0–2 and division by a constant; parts made of constants alone are
/// evaluated here, once), and the instructions left for eval() to run. Immutable: one plan
/// is shared by every thread.
class TapeRayPlan {
public:
    /// Throws std::invalid_argument for a tape with noise or an external field (accepts()).
    explicit TapeRayPlan(const Tape& tape);
    /// Whether a plan can be made for the tape: no Noise and no Field instruction (the
    /// implicit forms of closed-form primitives hold neither; callers keep
    /// Tape::evalIntervalAlongRay for the others).
    static bool accepts(const Tape& tape);

    /// A polynomial part: its operation on earlier polynomial parts (a, b index `polys`).
    struct Poly {
        Op op;
        int8_t maxDegree;  ///< 0: a constant, then `constant` is its enclosure
        int32_t a;
        int32_t b;
        double value;
        Interval constant;
    };
    /// An instruction eval() runs: a polynomial part's range (poly, index `source` into
    /// `polys`) or the tape's operation on earlier steps a, b.
    struct Step {
        Op op;
        bool poly;
        bool nonNegative;  ///< the real function it computes is ≥ 0 wherever defined
        int32_t a;
        int32_t b;
        int32_t source;
        double value;
    };

    const std::vector<Poly>& polys() const { return mPolys; }
    const std::vector<Step>& steps() const { return mSteps; }

private:
    std::vector<Poly> mPolys;
    std::vector<Step> mSteps;
};

/// A plan specialised to one ray: the coefficients of its polynomial parts. Per thread.
class TapeRayProgram {
public:
    /// The plan must outlive the program's use.
    void prepare(const TapeRayPlan& plan, const Ray& ray);

    /// Enclosures of f and of df/dt over t (the contract of Tape::evalIntervalAlongRay).
    void eval(const Interval& t, Interval& f, Interval& dfdt);

    /// f and df/dt at a point t, in doubles: the polynomial parts from their coefficients
    /// (rounded to doubles), the rest as Tape::evalGradient does. An approximation like
    /// Tape::eval (the coefficient form rounds differently from the tape's own order of
    /// operations); root isolation only needs point values that are consistent with each
    /// other.
    double valueAndSlope(double t, double& dfdt);
    double value(double t) {
        double ignored;
        return valueAndSlope(t, ignored);
    }

    /// A polynomial part along the ray: c0 + c1·t + c2·t², coefficients as intervals holding
    /// the exact real ones.
    struct Coefficients {
        Interval c[3];
        double m[3];  ///< c rounded to doubles, for point values
        int8_t deg;
        bool definite;       ///< deg 2 and c2 of one sign
        bool extremumReady;  ///< `extremum` is computed (on first use)
        Interval extremum;   ///< the value at the vertex: c0 − c1²/(4·c2)
    };

private:
    const TapeRayPlan* mPlan = nullptr;
    std::vector<Coefficients> mCoefficients;
};

}  // namespace kerf
