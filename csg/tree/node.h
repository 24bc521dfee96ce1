/// @file csg/tree/node.h
/// @brief The solid-tree interface: every primitive, transform, material and Boolean node is a
/// Node. Trees are immutable once built and shared freely between objects and threads
/// (an instance is the same subtree under another transform).
#pragma once

#include "csg/interval/interval.h"
#include "csg/trace_context.h"
#include "csg/tree/node_kind.h"
#include "csg/tree/span.h"
#include "csg/types.h"

#include <memory>
#include <vector>

namespace kerf {

/// Points in extended precision, for reference computations (csg/primitives/reference.h).
using LVec3 = glm::tvec3<long double>;

/// A box of points as three intervals, for interval evaluation of implicit forms.
struct IntervalVec3 {
    Interval x, y, z;
};

class Node {
public:
    virtual ~Node() = default;

    /// A box holding the solid, in this node's own space (the space of its parent).
    /// May be unbounded (half-spaces); never smaller than the solid.
    const Bounds3& bounds() const { return mBounds; }

    /// Writes into `out` (cleared first) the spans where the ray is inside the solid, sorted.
    /// They must be exact on [tmin, tmax]; outside it they may be clipped (a clipped end is a
    /// Boundary with primitive 0) or omitted. The caller has not necessarily tested bounds.
    virtual void spans(const Ray& ray, double tmin, double tmax, TraceContext& ctx,
                       SpanList& out) const = 0;

    /// The first surface crossing with tmin < t ≤ tmax, as the first surface boundary of
    /// spans() would give it (`entering` says which way the ray crosses). Leaves override it to
    /// stop searching at the first crossing, which a ray needs when no CSG is above it.
    virtual bool firstSurface(const Ray& ray, double tmin, double tmax, TraceContext& ctx,
                              Boundary& hit, bool& entering) const;

    /// Whether firstSurface would find a crossing (shadow rays). Wrappers pass it down, and a
    /// leaf whose every crossing is a surface (a mesh) may stop at any one, not the nearest.
    virtual bool anySurface(const Ray& ray, double tmin, double tmax, TraceContext& ctx) const {
        Boundary hit;
        bool entering = false;
        return firstSurface(ray, tmin, tmax, ctx, hit, entering);
    }

    /// The implicit form: ≤ 0 inside, > 0 outside. Its magnitude is not a distance.
    virtual double value(const Vec3& p) const = 0;
    /// An interval holding value(p) for every p in the box.
    virtual Interval valueInterval(const IntervalVec3& box) const = 0;
    /// value(p) evaluated in long double throughout (same zero set), for the reference that
    /// accuracy is measured against.
    virtual long double valueExtended(const LVec3& p) const = 0;

    /// How many primitive leaves (shared subtrees counted per use) and how deep the tree is
    /// (a leaf has depth 1; every node counts): treeStats (csg/tree/tree_stats.h), one memoised
    /// walk, for one tree. Summaries of many trees call treeStats once for all.
    int64_t primitiveCount() const;
    int depth() const;

    // The open tree: enough for code outside csg/ to walk, print and rebuild trees.

    /// Which kind of node this is.
    virtual NodeKind kind() const = 0;
    /// The data that defines this node besides its children (csg/tree/node_kind.h).
    virtual NodeParams params() const = 0;
    /// The children, in order (a difference's body first); empty for a leaf.
    virtual NodeSpan children() const { return {}; }
    /// The same node over other children (as many as the kind allows: one for a transform or
    /// a material, at least one for a Boolean). Transforms keep their exact inverse, so the
    /// rebuilt node gives the same bits where the children do. A leaf returns nullptr.
    virtual NodePtr withChildren(std::vector<NodePtr> children) const { return nullptr; }

protected:
    Bounds3 mBounds;
};

/// The first surface boundary with tmin < t ≤ tmax in sorted spans; false if there is none.
bool firstSurfaceOf(const SpanList& spans, double tmin, double tmax, Boundary& hit, bool& entering);

}  // namespace kerf
