/// @file csg/tape/tape_along_ray.h
/// @brief A tape's f along a ray, in the form root isolation (csg/primitives/root_isolation.h)
/// wants: enclosures of f and df/dt over t-intervals, point values and slopes, and rigorous
/// enclosures at points for the certified steps of csg/primitives/lipschitz_step.h. Internal to
/// csg/ (the implicit primitive and its tests).
#pragma once

#include "csg/interval/interval_round.h"
#include "csg/tape/tape.h"

namespace kerf {

/// (The centred form f(m) + f'([a, b])·([a, b] − m), intersected with the natural enclosure
/// wherever that is ambiguous, was measured on the gyroid ∩ sphere at 160×120: 11.6 % fewer
/// interval evaluations, but 41 % more instructions, since f(m) needs a second interval
/// evaluation per call.)
struct TapeAlongRay {
    const Tape& tape;
    const Ray& ray;
    /// Try a certified step (csg/primitives/lipschitz_step.h) before each bisection. On: measured
    /// on the gyroid, Barth's sextic and the blobs (bench/), it cut instructions on all three.
    bool certifiedSteps = true;
    /// Only steps that clear the whole piece (a mean-value exclusion from both ends). Partial
    /// steps (0.25, 0.5 of the piece) were measured too: slower on the gyroid and the blobs,
    /// under 1 % faster on Barth's sextic, so no case keeps them.
    double minCertifiedShrink = 1.0;

    void range(double a, double b, Interval& f, Interval& dfdt) const {
        tape.evalIntervalAlongRay(ray, Interval(a, b), f, dfdt);
    }
    double value(double t) const { return tape.eval(ray.at(t)); }
    double valueAndSlope(double t, double& dfdt) const { return tape.evalAlongRay(ray, t, dfdt); }

    /// o + t·d on one axis, rounded outward (inline: this runs for every certified step).
    static Interval alongAxis(double o, double d, double t) {
        if (d == 0.0) return Interval(o);
        const double p = t * d;
        using interval_kernel::down, interval_kernel::up;
        return {down(o + down(p)), up(o + up(p))};
    }

    /// Enclosures of f at n ≤ 4 points of the ray in one four-lane evaluation: each point's
    /// box holds the exact o + t·d (outward rounding).
    void enclosuresAt(const double* t, int n, Interval* f) const {
        Interval box[3][4], out[4];
        for (int k = 0; k < 4; ++k) {
            const double tk = t[k < n ? k : n - 1];
            for (int axis = 0; axis < 3; ++axis)
                box[axis][k] = alongAxis(ray.origin[axis], ray.dir[axis], tk);
        }
        tape.evalInterval4(box[0], box[1], box[2], out);
        for (int k = 0; k < n; ++k) f[k] = out[k];
    }
};

}  // namespace kerf
