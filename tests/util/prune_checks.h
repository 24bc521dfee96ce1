/// @file tests/util/prune_checks.h
/// @brief The property pruned(node, box) promises (csg/tree/prune.h), checked at random points and
/// on random rays inside the box, and counters of what pruning leaves (primitives, tape
/// instructions) for the reports.
#pragma once

#include <catch2/catch.hpp>
#include <cmath>
#include <sstream>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "csg/tape/tape.h"
#include "csg/tree/prune.h"
#include "util/oracles.h"

namespace kerf::test {

/// Where |value| is below this the sign may differ: a difference whose cutter is Full over
/// the box is Empty, but max(v, −c) is exactly 0 (inside) where c = 0; and the torus' value
/// (hypot) and its interval extension (sqrt of squares) round differently within an ulp.
/// Scenes in these tests are of size ~1, so 1e-9 is far above either effect.
constexpr double kPruneSignSlack = 1e-9;

/// Spans and gaps thinner than this (rays have unit direction, scenes size ~1) are ignored
/// when spans are compared: at a tangency interval isolation of two different tapes may
/// report a touch on one and a sliver on the other.
constexpr double kPruneThin = 1e-7;
/// Crossings found by root isolation (tolerance 1e-9 of t) may move by this much.
constexpr double kPruneSpanSlack = 1e-8;

/// "kind(child, child…)": the tree's shape, through the open-tree API only.
inline std::string describeTree(const Node& node) {
    std::string s = nodeKindName(node.kind());
    if (node.children().empty()) return s;
    s += '(';
    for (size_t i = 0; i < node.children().size(); ++i) {
        if (i) s += ", ";
        s += describeTree(*node.children()[i]);
    }
    return s + ')';
}

/// Tape instructions in the implicit leaves (each use of a shared subtree counts).
inline int tapeInstructions(const Node& node) {
    if (node.kind() == NodeKind::Implicit)
        return std::get<ImplicitParams>(node.params()).tape->size();
    int n = 0;
    for (const NodePtr& c : node.children()) n += tapeInstructions(*c);
    return n;
}

inline Vec3 pointIn(const Bounds3& b, Random& rng) {
    return {rng.uniform(b.lo.x, b.hi.x), rng.uniform(b.lo.y, b.hi.y), rng.uniform(b.lo.z, b.hi.z)};
}

/// Spans clipped to [t0, t1], slivers dropped and thin gaps closed.
inline std::vector<Span> spansInside(const SpanList& spans, double t0, double t1) {
    std::vector<Span> out;
    for (Span s : spans) {
        if (s.in.t < t0) s.in.t = t0, s.in.primitive = 0;
        if (s.out.t > t1) s.out.t = t1, s.out.primitive = 0;
        if (!(s.out.t - s.in.t > kPruneThin)) continue;
        if (!out.empty() && s.in.t - out.back().out.t <= kPruneThin)
            out.back().out = s.out;
        else
            out.push_back(s);
    }
    return out;
}

/// The spans of a pruned result on [t0, t1]: none (Empty), all of it (Full), or its node's.
inline std::vector<Span> prunedSpans(const Pruned& p, const Ray& ray, double t0, double t1) {
    if (p.state == PruneState::Empty) return {};
    if (p.state == PruneState::Full) {
        Span s;
        s.in.t = t0;
        s.out.t = t1;
        return {s};
    }
    TraceContext ctx;
    SpanList spans;
    p.node->spans(ray, t0, t1, ctx, spans);
    return spansInside(spans, t0, t1);
}

/// Checks the pruned result against the original at `points` random points and on `rays`
/// random rays through the box. Returns the number of disagreements (each also a failed CHECK).
inline int checkPrunedAgrees(const NodePtr& original, const Pruned& p, const Bounds3& box,
                             Random& rng, int points, int rays) {
    int failures = 0;
    INFO("tree " << describeTree(*original));
    INFO("box " << box.lo.x << ' ' << box.lo.y << ' ' << box.lo.z << " .. " << box.hi.x << ' '
                << box.hi.y << ' ' << box.hi.z << " state " << int(p.state));
    INFO("pruned " << (p.state == PruneState::Partial ? describeTree(*p.node) : "-"));
    for (int i = 0; i < points; ++i) {
        const Vec3 q = pointIn(box, rng);
        const double v = original->value(q);
        if (std::fabs(v) <= kPruneSignSlack) continue;
        const bool inside = v <= 0.0;
        const bool prunedInside = p.state == PruneState::Full ||
                                  (p.state == PruneState::Partial && p.node->value(q) <= 0.0);
        if (inside == prunedInside) continue;
        ++failures;
        INFO("point " << q.x << ' ' << q.y << ' ' << q.z << " value " << v);
        CHECK(prunedInside == inside);
    }
    for (int i = 0; i < rays; ++i) {
        const Ray ray{pointIn(box, rng), rng.unitVector()};
        double t0 = -kInf, t1 = kInf;
        if (!box.clipRay(ray, t0, t1)) continue;
        TraceContext ctx;
        SpanList spans;
        original->spans(ray, t0, t1, ctx, spans);
        const std::vector<Span> a = spansInside(spans, t0, t1);
        const std::vector<Span> b = prunedSpans(p, ray, t0, t1);
        bool same = a.size() == b.size();
        for (size_t k = 0; same && k < a.size(); ++k) {
            same = std::fabs(a[k].in.t - b[k].in.t) <= kPruneSpanSlack &&
                   std::fabs(a[k].out.t - b[k].out.t) <= kPruneSpanSlack;
            // The same surface on both sides (pruned leaves keep their ids), same normal.
            for (const auto& [x, y] : {std::pair(a[k].in, b[k].in), std::pair(a[k].out, b[k].out)})
                if (same && x.isSurface() && y.isSurface())
                    same =
                        x.primitive == y.primitive &&
                        glm::dot(glm::normalize(x.normal), glm::normalize(y.normal)) > 1.0 - 1e-6;
        }
        if (same) continue;
        ++failures;
        INFO("ray " << ray.origin.x << ' ' << ray.origin.y << ' ' << ray.origin.z << " dir "
                    << ray.dir.x << ' ' << ray.dir.y << ' ' << ray.dir.z << " on [" << t0 << ", "
                    << t1 << "]");
        std::ostringstream text;
        text.precision(17);
        text << "original";
        for (const Span& s : a) text << " [" << s.in.t << ", " << s.out.t << "]";
        text << " / pruned";
        for (const Span& s : b) text << " [" << s.in.t << ", " << s.out.t << "]";
        INFO(text.str());
        CHECK(same);
    }
    return failures;
}

}  // namespace kerf::test
