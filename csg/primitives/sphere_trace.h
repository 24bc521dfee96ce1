/// @file csg/primitives/sphere_trace.h
/// @brief TraceMethod::SphereTrace: sphere tracing (Hart 1996) of a primitive's implicit form
/// with a Lipschitz bound, for the accuracy comparison only.
///
/// Deliberately the standard algorithm, not a better one: march t += |f(p)| / (L·|d|) until
/// |f| ≤ relTolerance·|t|·|d| (the crossing, not refined), step one tolerance past it and
/// march on |f| to the next one; give up after kSphereTraceMaxSteps steps per crossing
/// searched (the rest of the range keeps its state). It slows down on grazing rays and gives
/// up there, and steps over anything thinner than its tolerance; with an underestimated L
/// (the implicit's is estimated) it can step over surfaces. That is what the comparison shows.
#pragma once

#include "csg/primitives/root_isolation.h"
#include "csg/trace_context.h"
#include "csg/tree/span.h"

#include <algorithm>
#include <cmath>

namespace kerf {

/// Steps per crossing searched before giving up.
constexpr int kSphereTraceMaxSteps = 512;

/// Calls sink(t, entering) for each crossing met marching from t0 (finite) towards t1 along
/// the ray; returns whether t0 is inside. value(p) is the implicit form (≤ 0 inside) and
/// |∇value| ≤ lipschitz is assumed. `outsideBefore`: the ray is known to be outside just
/// before t0 (t0 on a bounding box that may share the surface, as a box's does), so a start
/// on the surface is a crossing. Each step counts in ctx.stats.rootSteps.
template <class Value, class Sink>
bool sphereTraceCrossings(const Value& value, const Ray& ray, double t0, double t1,
                          double lipschitz, bool outsideBefore, TraceContext& ctx, Sink&& sink) {
    const double len = std::sqrt(glm::dot(ray.dir, ray.dir));
    const double speed = lipschitz * len;  // |value| changes at most this much per unit t
    double t = t0;
    double f = value(ray.at(t));
    const bool startInside = !outsideBefore && isInside(f);
    bool inside = startInside;
    // A crossing counts once |f| has left the tolerance band; a ray starting on the surface
    // must first move off it, unless it is known to come from outside.
    bool armed = outsideBefore || std::fabs(f) > ctx.relTolerance * std::fabs(t) * len;
    int steps = 0;
    for (;;) {
        const double tol = ctx.relTolerance * std::fabs(t) * len;
        const double af = std::fabs(f);
        if (af <= tol) {
            if (armed) {
                inside = !inside;
                sink(t, inside);
                armed = false;
                steps = 0;
            }
        } else {
            // Past the band on the other side without stopping in it: a surface was stepped
            // over (only when L underestimates the gradient). Recorded late, where noticed.
            if (isInside(f) != inside) {
                inside = !inside;
                sink(t, inside);
                steps = 0;
            }
            armed = true;
        }
        if (++steps > kSphereTraceMaxSteps) break;
        ++ctx.stats.rootSteps;
        const double next = t + std::max(af, tol) / speed;
        if (!(next <= t1) || next == t) break;  // past the range, NaN, or stuck on rounding
        t = next;
        f = value(ray.at(t));
    }
    return startInside;
}

/// Spans from sphereTraceCrossings over [t0, t1]: surface(t) makes the boundary of a crossing,
/// end(t, atStart) the boundary of the range end at t where the ray is inside there. Spans
/// thinner than the tolerance are dropped, as for the other methods.
template <class Value, class Surface, class End>
void sphereTraceSpans(const Value& value, const Ray& ray, double t0, double t1, double lipschitz,
                      bool outsideBefore, TraceContext& ctx, Surface&& surface, End&& end,
                      SpanList& out) {
    Boundary pending;
    bool havePending = false;  // an entering crossing waiting for its exit
    int crossings = 0;
    const bool startInside = sphereTraceCrossings(
        value, ray, t0, t1, lipschitz, outsideBefore, ctx, [&](double t, bool entering) {
            ++crossings;
            if (entering) {
                pending = surface(t);
                havePending = true;
            } else {
                out.push_back({havePending ? pending : end(t0, true), surface(t)});
                havePending = false;
            }
        });
    const bool insideAtEnd = crossings == 0 ? startInside : havePending;
    if (insideAtEnd) out.push_back({havePending ? pending : end(t0, true), end(t1, false)});
    dropThinSpans(out, ctx.relTolerance);
}

}  // namespace kerf
