/// @file csg/primitives/comparison_methods.h
/// @brief TraceMethod::Interval and TraceMethod::SphereTrace for every primitive, from its
/// implicit form alone (Primitive::implicitExpr), for `--method` and the accuracy comparison.
/// A primitive brings only its closed form (if any) and its implicit form; a new primitive
/// gets both comparison methods for free.
///
/// - Interval: the implicit primitive's own machinery (csg/primitives/implicit.cpp: interval root
///   isolation along the ray, clipped to the bounds) run on a stand-in implicit over the
///   primitive's form, bounds and id, whose enclosures come from the tape specialised to the
///   ray (csg/tape/tape_ray_program.h: quadratics along the ray get their exact range). An infinite
///   end of the range (half-spaces) is first moved to a finite one beyond which interval
///   evaluation proves the state cannot change.
/// - SphereTrace: Hart's march (csg/primitives/sphere_trace.h) on value() with the primitive's
/// Lipschitz
///   bound, within its bounds; a crossing's normal is the gradient of the form.
///
/// Neither is on the default path: ClosedFormPrimitive::spans takes one predictable branch.
#pragma once

#include "csg/primitives/primitive.h"
#include "csg/tape/tape.h"

namespace kerf {

/// Node::spans of `p` by ctx.method, which is Interval or SphereTrace.
void comparisonSpans(const Primitive& p, const Ray& ray, double tmin, double tmax,
                     TraceContext& ctx, SpanList& out);

/// Node::firstSurface of `p` by ctx.method, which is Interval or SphereTrace: the first
/// surface boundary comparisonSpans would give, the interval search stopping once it is decided.
bool comparisonFirstSurface(const Primitive& p, const Ray& ray, double tmin, double tmax,
                            TraceContext& ctx, Boundary& hit, bool& entering);

/// p's implicit form compiled: an implicit's own tape; for other primitives compiled once per
/// thread on first use and kept by primitive id, so primitives carry nothing for these methods.
const Tape& implicitTape(const Primitive& p);

}  // namespace kerf
