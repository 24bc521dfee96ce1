// Union, intersection and xor are commutative: every order of the children must give the same
// spans. Orders differ in what each fold sees (a later intersection operand is searched only
// over the earlier ones' extent, so it comes back clipped there), which is exactly where a
// tie between a clip and a surface at the same t once lost the entry face.
#include "util/random_solids.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <numeric>
#include <sstream>

using namespace kerf;
using namespace kerf::test;

namespace {

const char* opName(BoolOp op) {
    switch (op) {
        case BoolOp::Union: return "union";
        case BoolOp::Intersection: return "intersection";
        case BoolOp::Difference: return "difference";
        case BoolOp::Xor: return "xor";
    }
    return "?";
}

std::string describe(const SpanList& s) {
    std::ostringstream o;
    o.precision(17);
    for (const Span& x : s)
        o << "[" << x.in.t << " p" << x.in.primitive << ", " << x.out.t << " p" << x.out.primitive
          << "] ";
    return o.str();
}

Vec3 unitOrZero(const Vec3& v) {
    const double l = glm::length(v);
    return l > 0.0 ? v / l : v;
}

/// Whether two boundaries agree: the same surface-or-clip status and primitive, t within the
/// boundaries' own error (root-found ones are isolated afresh over each order's range), and
/// the same normal direction for surfaces.
bool sameBoundary(const Boundary& a, const Boundary& b) {
    if (a.isSurface() != b.isSurface() || a.primitive != b.primitive) return false;
    if (std::isinf(a.t) || std::isinf(b.t)) return a.t == b.t;
    const double rel = 4.0 * std::max<double>(a.relError, b.relError) + 64.0 * kUlp;
    if (std::fabs(a.t - b.t) > rel * std::max({1.0, std::fabs(a.t), std::fabs(b.t)})) return false;
    if (!a.isSurface()) return true;
    return glm::length(unitOrZero(a.normal) - unitOrZero(b.normal)) <= 1e-6;
}

/// The spans as far as they are defined: on [0, ∞) (outside the range asked for, a node may
/// clip or omit them), with a part before 0 cut there by a clip.
SpanList withinRange(const SpanList& s) {
    SpanList r;
    for (Span x : s) {
        if (!(x.out.t > 0.0)) continue;
        if (x.in.t < 0.0) x.in = Boundary{};
        r.push_back(x);
    }
    return r;
}

bool sameSpans(const SpanList& a, const SpanList& b) {
    if (a.size() != b.size()) return false;
    for (int k = 0; k < a.size(); ++k)
        if (!sameBoundary(a[k].in, b[k].in) || !sameBoundary(a[k].out, b[k].out)) return false;
    return true;
}

}  // namespace

TEST_CASE("Boolean nodes: every order of a commutative operation's children gives the same spans",
          "[boolean][property]") {
    const BoolOp ops[] = {BoolOp::Union, BoolOp::Intersection, BoolOp::Xor};
    const TraceMethod methods[] = {TraceMethod::Closed, TraceMethod::Interval};
    Random rnd(20261127);
    int compared = 0, nonEmpty = 0, mismatches = 0;
    for (int scene = 0; scene < 600; ++scene) {
        const BoolOp op = ops[scene % 3];
        const int n = 2 + (scene / 3) % 3;  // 2, 3 and 4 children
        std::vector<NodePtr> children;
        std::vector<PrimitiveKind> kinds;
        for (int i = 0; i < n; ++i) {
            kinds.push_back(randomKind(rnd));
            children.push_back(randomPrimitive(rnd, kinds.back()));
        }
        for (int r = 0; r < 40; ++r) {
            const Ray ray = randomRayWithZeros(rnd);
            for (TraceMethod method : methods) {
                TraceContext ctx;
                ctx.method = method;
                ctx.relTolerance = 1e-9;
                std::vector<size_t> order(static_cast<size_t>(n));
                std::iota(order.begin(), order.end(), size_t(0));
                SpanList first;
                bool haveFirst = false;
                do {
                    std::vector<NodePtr> permuted;
                    for (size_t i : order) permuted.push_back(children[i]);
                    SpanList s;
                    makeBoolean(op, permuted)->spans(ray, 0.0, kInf, ctx, s);
                    s = withinRange(s);
                    if (!haveFirst) {
                        nonEmpty += !s.empty();
                        first = s;
                        haveFirst = true;
                        continue;
                    }
                    ++compared;
                    if (sameSpans(first, s)) continue;
                    if (++mismatches > 5) continue;  // report a few in full, count the rest
                    std::ostringstream kindList;
                    for (size_t i : order) kindList << int(kinds[i]) << " ";
                    FAIL_CHECK(opName(op)
                               << " of kinds (in this order) " << kindList.str() << "method "
                               << int(method) << " ray " << ray.origin.x << "," << ray.origin.y
                               << "," << ray.origin.z << " dir " << ray.dir.x << "," << ray.dir.y
                               << "," << ray.dir.z << "\n  first order: " << describe(first)
                               << "\n  this order:  " << describe(s));
                } while (std::next_permutation(order.begin(), order.end()));
            }
        }
    }
    INFO("orders compared: " << compared << ", rays with spans: " << nonEmpty
                             << ", mismatches: " << mismatches);
    CHECK(mismatches == 0);
    CHECK(compared > 200000);
    CHECK(nonEmpty > 8000);
}
