// Union, intersection, difference and xor nodes. Children the ray cannot reach within the
// current parameter range are skipped by their bounds; wide unions and the cutters of a
// difference are found through a BVH, so a box minus 1000 spheres tests a handful of spheres.
#include "csg/bvh/bvh.h"
#include "csg/bvh/clip_ray.h"
#include "csg/check.h"
#include "csg/tree/kind_registry.h"
#include "csg/tree/repeated_instances.h"
#include "csg/tree/solids.h"

#include <algorithm>

namespace kerf {

namespace {

// Below this many candidates a linear scan of bounds beats walking a tree.
constexpr size_t kBvhThreshold = 4;

/// The implicit form (≤ 0 inside) of `op` applied to two operands' forms v and c, for
/// double, long double and Interval alike.
template <class T>
T combineValues(BoolOp op, const T& v, const T& c) {
    using std::max;
    using std::min;
    switch (op) {
        case BoolOp::Union: return min(v, c);
        case BoolOp::Intersection: return max(v, c);
        case BoolOp::Difference: return max(v, -c);
        case BoolOp::Xor: return max(min(v, c), -max(v, c));
    }
    return v;
}

class BooleanNode final : public Node {
public:
    BooleanNode(BoolOp op, std::vector<NodePtr> children)
        : mOp(op), mChildren(std::move(children)) {
        KERF_DCHECK(!mChildren.empty());  // makeBoolean's caller gives the operands
        std::vector<Bounds3> boxes;
        for (const NodePtr& c : mChildren) boxes.push_back(c->bounds());
        mBounds = boxes[0];
        for (size_t i = 1; i < boxes.size(); ++i) {
            if (mOp == BoolOp::Intersection)
                mBounds = Bounds3::overlap(mBounds, boxes[i]);
            else if (mOp != BoolOp::Difference)
                mBounds = Bounds3::hull(mBounds, boxes[i]);
        }
        // The BVH covers the operands that are found by search: all of a union, the cutters
        // of a difference (index i in the tree is child i + mFirstSearched).
        mFirstSearched = (mOp == BoolOp::Difference) ? 1 : 0;
        const bool searchable = mOp == BoolOp::Union || mOp == BoolOp::Difference;
        if (searchable && mChildren.size() - mFirstSearched > kBvhThreshold) {
            mUseBvh = true;
            mBvh = Bvh(std::vector<Bounds3>(boxes.begin() + mFirstSearched, boxes.end()));
        }
        // An intersection of a root-found operand with a closed-form one is searched inside
        // the closed-form operand's spans only (guidedFirstSurface).
        if (mOp == BoolOp::Intersection && mChildren.size() == 2) {
            const bool found0 = hasRootFoundLeaf(*mChildren[0]);
            const bool found1 = hasRootFoundLeaf(*mChildren[1]);
            if (found0 != found1) mGuide = found0 ? 1 : 0;
        }
    }

    void spans(const Ray& ray, double tmin, double tmax, TraceContext& ctx,
               SpanList& out) const override {
        out.clear();
        // Wide nodes compute the reciprocal direction once for the BVH and every child's box
        // test; for a few children three divisions per test cost less than making it.
        if (mUseBvh) {
            const RayReciprocal rec(ray);
            return spansWith(ray, &rec, tmin, tmax, ctx, out);
        }
        spansWith(ray, nullptr, tmin, tmax, ctx, out);
    }

    /// A union's first surface without its spans: where the ray starts outside every child,
    /// the union is entered first where the first child is (the nearest of the children's
    /// first surfaces, children searched near first with the range shrinking to it). Where a
    /// child's first surface is an exit, or a child without any crossing holds the candidate
    /// point (the ray is inside it throughout), the spans decide as for every other node.
    bool firstSurface(const Ray& ray, double tmin, double tmax, TraceContext& ctx, Boundary& hit,
                      bool& entering) const override {
        if (mOp == BoolOp::Intersection && mGuide >= 0)
            return guidedFirstSurface(ray, tmin, tmax, ctx, hit, entering);
        if (mOp != BoolOp::Union) return Node::firstSurface(ray, tmin, tmax, ctx, hit, entering);
        constexpr int kMaxSilent = 16;
        size_t silent[kMaxSilent];
        int silentCount = 0;
        bool found = false, undecided = false;
        Boundary best;
        // Children are searched up to a little past the best so far, so that one entering at
        // the same t (a shared face) is found there and not judged on a span cut to nothing.
        double reach = tmax;
        auto visit = [&](size_t i) {
            Boundary b;
            bool enters = true;
            if (!mChildren[i]->firstSurface(ray, tmin, reach, ctx, b, enters)) {
                if (silentCount == kMaxSilent)
                    undecided = true;
                else
                    silent[silentCount++] = i;
                return;
            }
            if (!enters) {
                undecided = true;
                return;
            }
            // Ties as combineSpans breaks them between two entering surfaces: primitive order.
            if (!found || b.t < best.t || (b.t == best.t && b.primitive < best.primitive)) {
                best = b;
                found = true;
                reach = std::min(tmax, b.t + 4.0 * ctx.relTolerance * std::fabs(b.t));
            }
        };
        if (mUseBvh) {
            const RayReciprocal rec(ray);
            mBvh.traverse(rec, tmin, tmax, ctx.stats, [&](int i, double tEnter) {
                if (!undecided && !(tEnter > reach)) visit(size_t(i));
                return undecided ? -kInf : reach;
            });
        } else {
            for (size_t i = 0; i < mChildren.size() && !undecided; ++i) {
                double t0 = tmin, t1 = reach;
                ++ctx.stats.boundsTests;
                if (clipRayExact(mChildren[i]->bounds(), ray, t0, t1)) visit(i);
            }
        }
        if (!undecided && found) {
            const Vec3 p = ray.at(best.t);
            for (int k = 0; k < silentCount && !undecided; ++k)
                undecided = mChildren[silent[k]]->value(p) <= 0.0;
        }
        if (undecided) return Node::firstSurface(ray, tmin, tmax, ctx, hit, entering);
        if (!found) return false;
        hit = best;
        entering = true;
        return true;
    }

    double value(const Vec3& p) const override {
        return combinedValue<double>([&](const Node& c) { return c.value(p); });
    }

    long double valueExtended(const LVec3& p) const override {
        return combinedValue<long double>([&](const Node& c) { return c.valueExtended(p); });
    }

    Interval valueInterval(const IntervalVec3& box) const override {
        return combinedValue<Interval>([&](const Node& c) { return c.valueInterval(box); });
    }

    NodeKind kind() const override { return booleanKind(mOp); }
    NodeParams params() const override { return BooleanParams{mOp}; }
    NodeSpan children() const override { return {mChildren.data(), mChildren.size()}; }
    NodePtr withChildren(std::vector<NodePtr> children) const override {
        return makeBoolean(mOp, std::move(children));
    }

private:
    /// Whether finding where the ray crosses `node` takes root isolation (an implicit or a
    /// torus below it), as opposed to closed forms only.
    static bool hasRootFoundLeaf(const Node& node) {
        if (kindTraits(node.kind()).rootFound) return true;
        for (const NodePtr& c : node.children())
            if (hasRootFoundLeaf(*c)) return true;
        return false;
    }

    /// X's state over [a, b] where it reported no crossing: 1 inside, 0 outside, −1 where its
    /// ends disagree (a crossing its spans dropped with a span thinner than the tolerance).
    static int stateThroughout(const Node& x, const Ray& ray, double a, double b) {
        const bool inA = x.value(ray.at(a)) <= 0.0, inB = x.value(ray.at(b)) <= 0.0;
        return inA != inB ? -1 : inA ? 1 : 0;
    }

    /// The first surface of G ∩ X, where G (the guide, closed form) has cheap spans and X is
    /// searched by root isolation: X is searched only inside G's spans, and only up to its
    /// first crossing there. In a span (a, b] of G, X's first crossing c decides: X entering
    /// at c means X is outside on (a, c), so the intersection is entered at c; X leaving at c
    /// means X is inside on (a, c), so the intersection is entered at a (or, where the ray
    /// starts inside G, left at c). Without a crossing X keeps its state at a throughout.
    /// The combined spans would drop a span or close a gap thinner than the tolerance; where
    /// another boundary lies that close after the candidate, the spans decide instead.
    bool guidedFirstSurface(const Ray& ray, double tmin, double tmax, TraceContext& ctx,
                            Boundary& hit, bool& entering) const {
        const Node& other = *mChildren[size_t(1 - mGuide)];
        ScratchSpans scratch(ctx.scratch);
        SpanList& gs = *scratch;
        if (!childSpans(size_t(mGuide), ray, nullptr, tmin, tmax, ctx, gs)) return false;
        for (int k = 0; k < gs.size(); ++k) {
            const Span& s = gs[k];
            if (s.in.t > tmax) break;
            if (!(s.in.t < s.out.t) || !(s.out.t > tmin)) continue;
            const bool entersGuide = s.in.t > tmin && s.in.isSurface();
            const bool leavesGuide = s.out.t <= tmax && s.out.isSurface();
            const double a = std::max(s.in.t, tmin), b = std::min(s.out.t, tmax);
            double t0 = a, t1 = b;
            ++ctx.stats.boundsTests;
            if (!clipRayExact(other.bounds(), ray, t0, t1)) continue;  // X is outside here
            Boundary c;
            bool xEnters = true;
            double spanEnd = kInf;  // where a span entered at hit ends, if known
            if (other.firstSurface(ray, a, b, ctx, c, xEnters)) {
                if (xEnters || !entersGuide) {
                    hit = c;  // entering X inside G, or leaving X while inside both
                    entering = xEnters;
                } else {
                    hit = s.in;
                    entering = true;
                    spanEnd = c.t;
                }
            } else if (const int state = stateThroughout(other, ray, a, std::min(b, t1));
                       state != 1) {
                if (state == 0) continue;  // X outside throughout the span
                return Node::firstSurface(ray, tmin, tmax, ctx, hit, entering);
            } else if (entersGuide) {
                hit = s.in;
                entering = true;
            } else if (leavesGuide) {
                hit = s.out;
                entering = false;
            } else {
                continue;
            }
            // The combined spans drop a span, or close a gap, no wider than the tolerance. X's
            // own spans already did so with its own crossings, so only G's boundaries and the
            // span from G's entry to X's exit can make one here (or, leaving, the start of
            // the range): where they lie that close, the spans decide.
            const double near = 2.0 * ctx.relTolerance * std::fabs(hit.t);
            const double guideNext =
                entering ? s.out.t : (k + 1 < gs.size() ? gs[k + 1].in.t : kInf);
            const bool crowded = guideNext - hit.t <= near || spanEnd - hit.t <= near ||
                                 (!entering && hit.t - tmin <= near);
            if (crowded) return Node::firstSurface(ray, tmin, tmax, ctx, hit, entering);
            return true;
        }
        return false;
    }

    void spansWith(const Ray& ray, const RayReciprocal* rec, double tmin, double tmax,
                   TraceContext& ctx, SpanList& out) const {
        switch (mOp) {
            case BoolOp::Union: return unionSpans(ray, rec, tmin, tmax, ctx, out);
            case BoolOp::Intersection: return intersectionSpans(ray, rec, tmin, tmax, ctx, out);
            case BoolOp::Difference: return differenceSpans(ray, rec, tmin, tmax, ctx, out);
            case BoolOp::Xor: return xorSpans(ray, rec, tmin, tmax, ctx, out);
        }
    }

    /// The children's implicit forms (valueOf(child)) combined left to right by the operator.
    template <class T, class ValueOf>
    T combinedValue(const ValueOf& valueOf) const {
        T v = valueOf(*mChildren[0]);
        for (size_t i = 1; i < mChildren.size(); ++i)
            v = combineValues<T>(mOp, v, valueOf(*mChildren[i]));
        return v;
    }

    /// Spans of child i if its bounds may meet the ray within [tmin, tmax]; else leaves `s`
    /// empty. `rec`: the ray's reciprocal direction if spans() made it, else null.
    bool childSpans(size_t i, const Ray& ray, const RayReciprocal* rec, double tmin, double tmax,
                    TraceContext& ctx, SpanList& s) const {
        double t0 = tmin, t1 = tmax;
        ++ctx.stats.boundsTests;
        const Bounds3& box = mChildren[i]->bounds();
        if (!(rec ? box.clipRayConservative(*rec, t0, t1) : clipRayExact(box, ray, t0, t1))) {
            s.clear();
            return false;
        }
        mChildren[i]->spans(ray, tmin, tmax, ctx, s);
        return !s.empty();
    }

    /// acc = acc op child.
    void fold(BoolOp op, SpanList& acc, const SpanList& child, TraceContext& ctx) const {
        ScratchSpans result(ctx.scratch);
        combineSpans(op, acc, child, ctx.relTolerance, *result);
        acc.assign(*result);
    }

    /// Calls f(childIndex) for every searched child whose bounds may meet the ray segment.
    template <class F>
    void forSearched(const Ray& ray, const RayReciprocal* rec, double tmin, double tmax,
                     TraceContext& ctx, F&& f) const {
        if (mUseBvh) {
            mBvh.traverse(*rec, tmin, tmax, ctx.stats, [&](int i, double) {
                f(static_cast<size_t>(i) + mFirstSearched);
                return tmax;
            });
        } else {
            for (size_t i = mFirstSearched; i < mChildren.size(); ++i) f(i);
        }
    }

    void unionSpans(const Ray& ray, const RayReciprocal* rec, double tmin, double tmax,
                    TraceContext& ctx, SpanList& out) const {
        ScratchSpans scratch(ctx.scratch);
        SpanList& child = *scratch;
        forSearched(ray, rec, tmin, tmax, ctx, [&](size_t i) {
            if (!childSpans(i, ray, rec, tmin, tmax, ctx, child)) return;
            if (out.empty())
                out.assign(child);
            else
                fold(BoolOp::Union, out, child, ctx);
        });
    }

    void intersectionSpans(const Ray& ray, const RayReciprocal* rec, double tmin, double tmax,
                           TraceContext& ctx, SpanList& out) const {
        // A closed-form guide goes first: the root-found operand is then searched only over
        // the guide's extent.
        const size_t first = mGuide > 0 ? size_t(mGuide) : 0;
        if (!childSpans(first, ray, rec, tmin, tmax, ctx, out)) return;
        ScratchSpans scratch(ctx.scratch);
        SpanList& child = *scratch;
        for (size_t k = 1; k < mChildren.size() && !out.empty(); ++k) {
            const size_t i = k == first ? 0 : k;
            // Only where every earlier operand is inside can the result be.
            const double lo = std::max(tmin, out[0].in.t), hi = std::min(tmax, out.back().out.t);
            if (!childSpans(i, ray, rec, lo, hi, ctx, child)) {
                out.clear();
                return;
            }
            fold(BoolOp::Intersection, out, child, ctx);
        }
    }

    void differenceSpans(const Ray& ray, const RayReciprocal* rec, double tmin, double tmax,
                         TraceContext& ctx, SpanList& out) const {
        if (!childSpans(0, ray, rec, tmin, tmax, ctx, out)) return;
        // Cutters matter only where the body is: search them over the body's extent.
        const double lo = std::max(tmin, out[0].in.t), hi = std::min(tmax, out.back().out.t);
        ScratchSpans scratch(ctx.scratch);
        SpanList& child = *scratch;
        forSearched(ray, rec, lo, hi, ctx, [&](size_t i) {
            if (out.empty() || !childSpans(i, ray, rec, lo, hi, ctx, child)) return;
            fold(BoolOp::Difference, out, child, ctx);
        });
    }

    void xorSpans(const Ray& ray, const RayReciprocal* rec, double tmin, double tmax,
                  TraceContext& ctx, SpanList& out) const {
        ScratchSpans scratch(ctx.scratch);
        SpanList& child = *scratch;
        for (size_t i = 0; i < mChildren.size(); ++i) {
            if (!childSpans(i, ray, rec, tmin, tmax, ctx, child)) continue;
            if (out.empty())
                out.assign(child);
            else
                fold(BoolOp::Xor, out, child, ctx);
        }
    }

    BoolOp mOp;
    const std::vector<NodePtr> mChildren;  // set once: trees are immutable
    size_t mFirstSearched = 0;
    int mGuide = -1;  ///< an intersection's closed-form operand that guides the search, or -1
    bool mUseBvh = false;
    Bvh mBvh;
};

}  // namespace

NodePtr makeBoolean(BoolOp op, std::vector<NodePtr> children) {
    children = withoutRepeatedInstances(op, std::move(children));
    if (children.size() == 1) return children[0];
    return std::make_shared<BooleanNode>(op, std::move(children));
}

}  // namespace kerf
