/// @file render/medium.h
/// @brief Transmittance through a heterogeneous medium (scene/medium.h): the ray's overlap
/// with the medium's box split into pieces, each with a control σc and a majorant μ from the
/// density's range over the piece (σc ≤ σt ≤ μ on the piece), and three estimators over
/// them: residual ratio tracking, delta tracking and deterministic marching. Distances are in
/// world units along a unit-direction ray. render/medium_transport.cpp uses these for camera,
/// secondary and shadow rays and for single scattering.
#pragma once

#include "csg/mix_bits.h"
#include "scene/medium.h"

#include <cstdint>

namespace kerf {

/// A counter-based stream of uniform numbers in [0, 1): its numbers depend only on its seed,
/// so a pixel sample draws the same numbers whatever thread renders it.
class MediumRandom {
public:
    explicit MediumRandom(uint64_t seed) : mState(mixBits(seed)) {}
    double next() { return double(mixBits(mState++) >> 11) * 0x1.0p-53; }

private:
    uint64_t mState;
};

/// One piece [t0, t1] of a ray inside the medium's box, with control ≤ σt ≤ majorant there.
struct MediumPiece {
    double t0 = 0.0, t1 = 0.0;
    double control = 0.0;
    double majorant = 0.0;
};

/// The pieces of a ray where the medium may be nonzero, in order along the ray. Pieces whose
/// range proves the density zero are left out (empty space costs one range() each). A piece
/// is split while its residual optical depth (μ − σc)·length exceeds kMaxResidualDepth, at
/// most kMaxPieceLevels times, so the bounds are tighter where the field varies. Few levels:
/// each split costs a range() per ray, and a looser majorant only adds (cheap) tracking
/// steps, which lower ratio tracking's variance (measured: docs/accuracy.md).
class MediumPath {
public:
    static constexpr int kMaxPieces = 64;
    static constexpr int kMaxPieceLevels = 2;
    static constexpr double kMaxResidualDepth = 0.5;

    /// ray.dir must be unit length. [tmin, tmax]: the part of the ray wanted (tmax may be inf).
    MediumPath(const Medium& medium, const Ray& ray, double tmin, double tmax);

    int size() const { return mCount; }
    const MediumPiece& operator[](int i) const { return mPieces[i]; }
    bool empty() const { return mCount == 0; }
    /// The majorant's optical depth over the whole path, Σ μ·length.
    double majorantDepth() const;
    /// Interval evaluations of the density spent building the path (for --stats and tests).
    int rangeCalls() const { return mRangeCalls; }

private:
    void split(const Medium& medium, const Ray& ray, double t0, double t1, int level);

    MediumPiece mPieces[kMaxPieces];
    int mCount = 0;
    int mRangeCalls = 0;
};

/// σt at p: extinction · density, 0 outside the box, negative density read as 0.
double extinctionAt(const Medium& medium, const Vec3& p);

/// Ratio tracking plays Russian roulette below this transmittance (unbiased).
constexpr double kRouletteThreshold = 0.05;
/// Ratio tracking's residual majorant is raised to give at least this many points per piece.
constexpr double kMinRatioSteps = 4.0;
/// Marching stops at this optical depth (T < 1e-6): the error it adds is below 1e-6.
constexpr double kMarchOpaqueDepth = 13.8155;

/// Residual ratio tracking over the path up to distance tEnd: exp(−σc·length) per piece times
/// Π (1 − (σt − σc)/(μ − σc)) at points spaced by the residual majorant. Unbiased.
double ratioTracking(const Medium& medium, const Ray& ray, const MediumPath& path, double tEnd,
                     MediumRandom& rng);
/// Delta tracking with the majorant: 1 if no real collision happens before tEnd, else 0.
double deltaTracking(const Medium& medium, const Ray& ray, const MediumPath& path, double tEnd,
                     MediumRandom& rng);
/// exp(−Σ σt(midpoint)·h) over steps of at most `step` within the path's pieces up to tEnd
/// (0 once the depth passes kMarchOpaqueDepth, unless tauError is asked for).
/// tauError (optional) receives the bound Σ (hi − lo)·h on |τ − τ_h| from the range over each
/// step (so |T − T_h| ≤ T_h·(e^bound − 1)).
double marchTransmittance(const Medium& medium, const Ray& ray, const MediumPath& path, double tEnd,
                          double step, double* tauError = nullptr);
/// The method's step: medium.step, or the box's diagonal / 128 when it is 0.
double marchStep(const Medium& medium);

/// The estimate the medium's method chooses, over the ray up to tmax.
double mediumTransmittance(const Medium& medium, const Ray& ray, double tmax, MediumRandom& rng);

/// A distance in the path drawn with density ∝ μ(t)·exp(−∫μ) conditioned on the path (the
/// majorant's free flight), from u in [0, 1). Returns false on an empty path; pdf receives
/// the density at t.
bool sampleMajorantDistance(const MediumPath& path, double u, double& t, double& pdf);

/// The Henyey–Greenstein phase function (per steradian) for the cosine between the light's
/// and the scattered direction of travel.
double henyeyGreenstein(double cosTheta, double g);

}  // namespace kerf
