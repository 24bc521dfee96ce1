/// @file csg/tape/tape.h
/// @brief A compiled expression: a flat, immutable list of instructions in evaluation order,
/// and the per-thread evaluators over it (point, interval, gradient).
#pragma once

#include "csg/interval/interval.h"
#include "csg/tape/expr.h"
#include "csg/types.h"

#include <memory>
#include <vector>

namespace kerf {

/// Which operand decided a min or max over a region (Fidget's Choice): Left (a), Right (b),
/// or Both when interval evaluation could not tell. abs(a) records Left where a > 0 (it is a)
/// and Right where a < 0 (it is −a). Other instructions record Both.
enum class Choice : uint8_t { Both, Left, Right };

/// Instruction i writes slot i; operands name earlier slots.
struct TapeInstr {
    Op op;
    int32_t a;
    int32_t b;
    int32_t c;  ///< the third operand of Noise and Field, else −1
    double value;
};

/// A Noise instruction's seed (held exactly in `value`).
inline uint64_t noiseSeed(const TapeInstr& in) { return static_cast<uint64_t>(in.value); }

/// A Field instruction's index in its tape's field table (Tape::fields).
inline size_t fieldIndex(const TapeInstr& in) { return static_cast<size_t>(in.value); }

/// An interval holding each partial derivative of the field: [−L, L] for L = lipschitz(), or
/// the whole line when L is not a finite bound. The interval slopes of Op::Field take it.
Interval lipschitzPartial(const ScalarField& field);

class Tape {
public:
    /// Compiles the part of the graph that `root` depends on.
    static std::shared_ptr<const Tape> compile(const ExprGraph& graph, ExprId root);

    const std::vector<TapeInstr>& instrs() const { return mInstrs; }
    int size() const { return static_cast<int>(mInstrs.size()); }
    /// The external fields Op::Field instructions call, by fieldIndex: those the compiled part
    /// of the graph uses, renumbered in order of first use; simplified() keeps the table.
    const std::vector<std::shared_ptr<const ScalarField>>& fields() const { return mFields; }
    /// The field a Field instruction calls.
    const ScalarField& field(const TapeInstr& in) const { return *mFields[fieldIndex(in)]; }

    /// f at a point.
    double eval(const Vec3& p) const;
    /// f at a point in long double throughout, for reference computations.
    long double evalExtended(const glm::tvec3<long double>& p) const;
    /// An interval holding f over the box.
    Interval evalInterval(const Interval& x, const Interval& y, const Interval& z) const;
    /// Which implementation evalInterval4 runs (tests and benchmarks name one; Auto is the
    /// rule below).
    enum class Lanes4 { Auto, Scalar, Avx2 };
    /// f over four boxes at once: out[k] holds f over x[k] × y[k] × z[k], and equals
    /// evalInterval(x[k], y[k], z[k]) bit for bit (lo, hi and maybeNan), whichever path runs
    /// (csg/tape/tape_eval_interval4.cpp). The slots are kept as structures of arrays, four lanes
    /// per instruction. Auto runs the AVX2 path (csg/tape/tape_eval_interval4_avx2.cpp) when the
    /// CPU has AVX2 and the environment variable KERF_SIMD is not "scalar" (both read once); the
    /// scalar path, a loop over the lanes with evalInterval's kernels, is the reference. The AVX2
    /// path vectorises const, x, y, z, +, −, ×, negation, square, sin, cos, min, max and abs; a
    /// tape with any other op runs the scalar path for all four lanes. Avx2 on a CPU without AVX2
    /// runs the scalar path.
    void evalInterval4(const Interval x[4], const Interval y[4], const Interval z[4],
                       Interval out[4], Lanes4 lanes = Lanes4::Auto) const;
    /// Whether this CPU can run evalInterval4's AVX2 path.
    static bool hasAvx2();
    /// f and its gradient at a point (forward-mode differentiation).
    double evalGradient(const Vec3& p, Vec3& gradient) const;
    /// f at ray.at(t) (the same bits as eval) and df/dt there: forward mode with one slope per
    /// slot instead of a gradient's three.
    double evalAlongRay(const Ray& ray, double t, double& dfdt) const;
    /// Along a ray p(t) = o + t·d for t in `t`: an interval holding f, and one holding df/dt
    /// (forward-mode differentiation on intervals). Used by root isolation.
    void evalIntervalAlongRay(const Ray& ray, const Interval& t, Interval& f, Interval& dfdt) const;
    /// The same, always by the general evaluator (per-slot NaN flags, every Op): the reference
    /// that evalIntervalAlongRay's lean path must equal bit for bit (tests).
    void evalIntervalAlongRayReference(const Ray& ray, const Interval& t, Interval& f,
                                       Interval& dfdt) const;

    /// evalInterval, also recording in `choices` (resized to size()) which operand of each
    /// min/max (and the sign of each abs) decided it over the box (csg/tape/tape_simplify.cpp).
    Interval evalInterval(const Interval& x, const Interval& y, const Interval& z,
                          std::vector<Choice>& choices) const;
    /// The tape with every decided min/max (abs) replaced by its chosen operand (or its
    /// negation) and the
    /// instructions nothing uses any more dropped (libfive, Fidget). On the box the choices
    /// were recorded over it computes the same doubles as this tape at every point.
    std::shared_ptr<const Tape> simplified(const std::vector<Choice>& choices) const;

private:
    /// Works out mLeanAlongRay once the instructions are final (compile, simplified).
    void finish();

    std::vector<TapeInstr> mInstrs;
    std::vector<std::shared_ptr<const ScalarField>> mFields;
    /// Every instruction is one that can never raise a NaN flag (constants, axes, +, −, ×,
    /// negation, square, sin, cos), so along-ray evaluation may skip the flags
    /// (csg/tape/tape_eval_ray.cpp).
    bool mLeanAlongRay = false;
};

}  // namespace kerf
