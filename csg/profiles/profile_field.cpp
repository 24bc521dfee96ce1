// A PathShape's signed distance: nearest point by segment (a small BVH over the segments'
// boxes), sign by crossing parity over y-monotone pieces.
#include "csg/profiles/profile_field.h"

#include "csg/bvh/bvh_builder.h"
#include "csg/profiles/path_geometry.h"
#include "csg/profiles/path_normals.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace kerf {

namespace {

using namespace path_geometry;

class PathField final : public ScalarField {
public:
    PathField(const PathField&) = delete;  // pieces point into mSegments
    PathField& operator=(const PathField&) = delete;
    explicit PathField(const PathShape& shape) {
        for (const PathLoop& loop : shape.loops)
            for (const PathSegment& s : loop.segments) mSegments.push_back(makeSegment(s));
        for (const Segment& s : mSegments) addPieces(s);
        buildTree();
        for (const Segment& s : mSegments)
            mScale = std::max({mScale, std::abs(s.box.lo.x), std::abs(s.box.lo.y),
                               std::abs(s.box.hi.x), std::abs(s.box.hi.y)});
    }

    double value(const Vec3& p) const override {
        const Nearest n = nearest(Vec2(p.x, p.y));
        return inside(Vec2(p.x, p.y)) ? -n.d : n.d;
    }
    long double valueExtended(const glm::tvec3<long double>& p) const override {
        return value(
            Vec3(static_cast<double>(p.x), static_cast<double>(p.y), static_cast<double>(p.z)));
    }
    double valueGradient(const Vec3& p, Vec3& gradient) const override {
        const Vec2 p2(p.x, p.y);
        const Nearest n = nearest(p2);
        const double sign = inside(p2) ? -1.0 : 1.0;
        const Vec2 away = p2 - n.q;
        const double scale = n.size + std::max(std::abs(n.q.x), std::abs(n.q.y));
        if (n.d > 0x1p-30 * scale) {  // p − q is accurate: the distance's own gradient
            gradient = Vec3(sign * away / n.d, 0.0);
        } else {  // on the outline: the segment's normal, turned to point out of the shape
            gradient = Vec3(outwardAt(n), 0.0);
        }
        return sign * n.d;
    }
    Interval range(const Interval& x, const Interval& y, const Interval&) const override {
        if (mSegments.empty()) return Interval(kInf, kInf);
        for (const Interval* a : {&x, &y})
            if (!std::isfinite(a->lo) || !std::isfinite(a->hi) || a->maybeNan)
                return Interval(-kInf, kInf);
        const Vec2 center(x.mid(), y.mid());
        const Vec2 half(std::max(x.hi - center.x, center.x - x.lo),
                        std::max(y.hi - center.y, center.y - y.lo));
        const double d = nearest(center).d;
        // 1-Lipschitz: every point of the box is within r of the centre. `err` covers the
        // Bézier refinement tolerance and rounding in d and r (a few operations on numbers no
        // larger than `scale`).
        const double r = glm::length(half) * (1.0 + 0x1p-50);
        const double scale =
            std::max({mScale, std::abs(center.x), std::abs(center.y)}) + std::max(half.x, half.y);
        const double err = (kCurveTolerance + 0x1p-40) * scale;
        const double hi = d + r + err;
        const double lo = d - r - err;
        if (lo > 0.0) return inside(center) ? Interval(-hi, -lo) : Interval(lo, hi);
        return Interval(-hi, hi);
    }

    Interval rangeGradient(const Interval& x, const Interval& y, const Interval& z,
                           Interval g[3]) const override {
        g[0] = g[1] = Interval(-1.0, 1.0);
        g[2] = Interval(0.0);  // z is ignored
        const Interval r = range(x, y, z);
        if (!std::isfinite(r.lo) || !std::isfinite(r.hi)) return r;
        // When one straight edge is the nearest feature for every point of the box, at an
        // interior point of it, the box holds no other outline: the sign flips only across
        // that edge and the field is the signed distance to its line — affine, its gradient
        // the edge's outward normal. Proven here with the 1-Lipschitz bounds used by range().
        const Vec2 center(x.mid(), y.mid());
        const Vec2 half(std::max(x.hi - center.x, center.x - x.lo),
                        std::max(y.hi - center.y, center.y - y.lo));
        const double rad = glm::length(half) * (1.0 + 0x1p-50);
        const double scale =
            std::max({mScale, std::abs(center.x), std::abs(center.y)}) + std::max(half.x, half.y);
        const double err = 0x1p-40 * scale;
        if (!(rad > 0x1p-30 * scale)) return r;  // too small for the side probe below
        const Nearest n = nearest(center);
        if (!n.segment) return r;
        if (n.segment->kind != PathSegment::Kind::Line) {
            curvedGradient(n, center, half, rad, err + kCurveTolerance * scale, g);
            return r;
        }
        const Segment& s = *n.segment;
        // Every other segment stays farther than this one from every point of the box.
        if (!(nearest(center, &s).d - rad - err > n.d + rad + err)) return r;
        // The foot of every point of the box lies strictly inside the edge.
        const Vec2 ab = s.b - s.a;
        const double len2 = glm::dot(ab, ab);
        if (!(len2 > 0.0)) return r;
        const double sc = glm::dot(center - s.a, ab) / len2;
        const double sr = (std::abs(ab.x) * half.x + std::abs(ab.y) * half.y) / len2;
        if (!(sc - sr > 0x1p-30 && sc + sr < 1.0 - 0x1p-30)) return r;
        // The outward side: a probe off the edge by rad/2 meets no other outline (the others
        // are more than 2·rad from the box).
        Vec2 normal = Vec2(-ab.y, ab.x) / std::sqrt(len2);
        if (inside(s.a + sc * ab + 0.5 * rad * normal)) normal = -normal;
        constexpr double kUlps = 0x1p-50;  // rounding in the normal's components
        g[0] = Interval(normal.x - kUlps, normal.x + kUlps);
        g[1] = Interval(normal.y - kUlps, normal.y + kUlps);
        return r;
    }

private:
    /// An outward unit normal at the outline point n.q: the segment's normal when probes on
    /// its two sides tell in from out; at a corner (where a probe along one edge's normal
    /// lands on the other edge) the mean of the directions around q that lead out.
    Vec2 outwardAt(const Nearest& n) const {
        const double step = 0x1p-24 * n.size;
        const bool ahead = inside(n.q + step * n.normal), behind = inside(n.q - step * n.normal);
        if (ahead != behind) return ahead ? -n.normal : n.normal;
        Vec2 sum(0.0);
        for (int k = 0; k < 16; ++k) {
            const double a = k * (kTwoPi / 16.0) + 0.1;  // off the axes, where edges often lie
            const Vec2 v(std::cos(a), std::sin(a));
            sum += inside(n.q + step * v) ? -v : v;
        }
        const double len = glm::length(sum);
        return len > 0.0 ? sum / len : n.normal;
    }

    /// rangeGradient where a Bézier or an arc is nearest to the box's centre: when it is the
    /// only outline within reach of the box, the field there is the signed distance to it,
    /// whose gradient is its outward normal at the feet (csg/profiles/path_normals.h bounds those).
    void curvedGradient(const Nearest& n, Vec2 center, Vec2 half, double rad, double err,
                        Interval g[3]) const {
        const Segment& s = *n.segment;
        // The foot of every point p of the box is within d(p) + rad ≤ d(center) + 2·rad.
        const double reach = n.d + 2.0 * rad + 2.0 * err;
        NormalSector sector;
        double clear = 0.0;
        if (!nearNormalSector(s, center, reach, sector, clear)) return;
        // No other segment within reach (the feet are on s) nor in the disc that holds the
        // part of s in reach (nothing crosses it, so the inside stays on one side of it).
        if (!(nearest(center, &s).d - err > std::max(clear, reach))) return;
        // Which side is out: from the point of the box farthest from the outline, whose
        // direction to its foot is accurate.
        Vec2 probe = center;
        Nearest m = n;
        for (const Vec2 corner : {Vec2(-1, -1), Vec2(1, -1), Vec2(-1, 1), Vec2(1, 1)}) {
            const Vec2 q = center + corner * half;
            const Nearest k = nearest(q);
            if (k.d > m.d) probe = q, m = k;
        }
        if (m.segment != &s ||
            !(m.d > 0x1p-30 * (m.size + std::max(std::abs(m.q.x), std::abs(m.q.y)))))
            return;
        const double out = (inside(probe) ? -1.0 : 1.0) * glm::dot(probe - m.q, m.normal) / m.d;
        if (!(std::abs(out) > 0.5)) return;
        const double turn = out > 0.0 ? 0.0 : 0.5 * kTwoPi;
        sectorBox(sector.lo + turn, sector.hi + turn, g[0], g[1]);
    }

    struct BvhNode {
        Bounds2 box;
        int first = 0, count = 0;  ///< a leaf's range in mOrder
        int left = -1, right = -1;
    };

    static Segment makeSegment(const PathSegment& in) {
        Segment s;
        s.kind = in.kind;
        s.a = in.start();
        s.b = in.end();
        switch (in.kind) {
            case PathSegment::Kind::Line: s.box = {glm::min(s.a, s.b), glm::max(s.a, s.b)}; break;
            case PathSegment::Kind::Arc: {
                Arc& arc = s.arc;
                arc.c = in.p[2];
                arc.r = 0.5 * (glm::length(s.a - arc.c) + glm::length(s.b - arc.c));
                arc.theta0 = std::atan2(s.a.y - arc.c.y, s.a.x - arc.c.x);
                const double theta1 = std::atan2(s.b.y - arc.c.y, s.b.x - arc.c.x);
                double sweep =
                    in.ccw ? wrapAngle(theta1 - arc.theta0) : wrapAngle(arc.theta0 - theta1);
                if (sweep == 0.0) sweep = kTwoPi;  // start = end: a full turn
                arc.sweep = in.ccw ? sweep : -sweep;
                s.box = {arc.c - Vec2(arc.r), arc.c + Vec2(arc.r)};
                break;
            }
            case PathSegment::Kind::Quadratic:
            case PathSegment::Kind::Cubic: {
                if (in.kind == PathSegment::Kind::Quadratic)
                    s.cubic = Cubic{{in.p[0], in.p[0] + (2.0 / 3.0) * (in.p[1] - in.p[0]),
                                     in.p[2] + (2.0 / 3.0) * (in.p[1] - in.p[2]), in.p[2]}};
                else
                    s.cubic = Cubic{{in.p[0], in.p[1], in.p[2], in.p[3]}};
                s.box = {s.cubic.p[0], s.cubic.p[0]};
                for (const Vec2& q : s.cubic.p) {
                    s.box.lo = glm::min(s.box.lo, q);
                    s.box.hi = glm::max(s.box.hi, q);
                }
                s.tolerance = kCurveTolerance * glm::length(s.box.hi - s.box.lo);
                break;
            }
        }
        return s;
    }

    void addPieces(const Segment& s) {
        if (s.kind == PathSegment::Kind::Line) {
            mPieces.push_back(
                {&s, s.a, s.b, std::min(s.a.x, s.b.x), std::max(s.a.x, s.b.x), {}, true});
            return;
        }
        if (s.kind == PathSegment::Kind::Arc) {
            // Split where the tangent is horizontal: angles π/2 + kπ inside the sweep.
            const Arc& arc = s.arc;
            std::vector<double> cuts = {0.0};
            const double step = arc.sweep > 0.0 ? 1.0 : -1.0;
            for (int k = -4; k <= 4; ++k) {
                const double theta = kTwoPi / 4.0 + k * (kTwoPi / 2.0);
                const double along =
                    step > 0 ? wrapAngle(theta - arc.theta0) : wrapAngle(arc.theta0 - theta);
                if (along > 0.0 && along < std::abs(arc.sweep) &&
                    std::find(cuts.begin(), cuts.end(), along) == cuts.end())
                    cuts.push_back(along);
            }
            std::sort(cuts.begin(), cuts.end());
            cuts.push_back(std::abs(arc.sweep));
            for (size_t i = 0; i + 1 < cuts.size(); ++i) {
                const double t0 = arc.theta0 + step * cuts[i], t1 = arc.theta0 + step * cuts[i + 1];
                const Vec2 a = i == 0 ? s.a : arc.at(t0);
                const Vec2 b = i + 2 == cuts.size() ? s.b : arc.at(t1);
                const bool right = std::cos(0.5 * (t0 + t1)) >= 0.0;
                mPieces.push_back({&s,
                                   a,
                                   b,
                                   right ? arc.c.x : arc.c.x - arc.r,
                                   right ? arc.c.x + arc.r : arc.c.x,
                                   {},
                                   right});
            }
            return;
        }
        const auto& p = s.cubic.p;
        const double a = 3.0 * (-p[0].y + 3.0 * p[1].y - 3.0 * p[2].y + p[3].y);
        const double b = 6.0 * (p[0].y - 2.0 * p[1].y + p[2].y);
        const double c = 3.0 * (p[1].y - p[0].y);
        std::vector<double> cuts = unitRoots(a, b, c);
        cuts.insert(cuts.begin(), 0.0);
        cuts.push_back(1.0);
        for (size_t i = 0; i + 1 < cuts.size(); ++i) {
            if (cuts[i + 1] <= cuts[i]) continue;
            Piece piece;
            piece.seg = &s;
            piece.cubic = s.cubic.part(cuts[i], cuts[i + 1]);
            piece.a = i == 0 ? s.a : piece.cubic.p[0];
            piece.b = i + 2 == cuts.size() ? s.b : piece.cubic.p[3];
            piece.cubic.p[0] = piece.a;
            piece.cubic.p[3] = piece.b;
            piece.xMin = piece.xMax = piece.a.x;
            for (const Vec2& q : piece.cubic.p) {
                piece.xMin = std::min(piece.xMin, q.x);
                piece.xMax = std::max(piece.xMax, q.x);
            }
            mPieces.push_back(piece);
        }
    }

    // The segment tree: the shared builder (csg/bvh/bvh_builder.h) with median splits on the
    // wider side of the node's box, four segments a leaf, equal keys as nth_element leaves
    // them (the key lo + hi, unhalved, is the tree's historic one).
    void buildTree() {
        std::vector<BvhBuildItem> items(mSegments.size());
        for (size_t i = 0; i < mSegments.size(); ++i) {
            const Bounds2& b = mSegments[i].box;
            items[i] = {Bounds3{Vec3(b.lo, 0.0), Vec3(b.hi, 0.0)},
                        Vec3(b.lo.x + b.hi.x, b.lo.y + b.hi.y, 0.0), uint32_t(i)};
        }
        BvhBuildRule rule;
        rule.split = BvhBuildRule::Split::Median;
        rule.maxLeafSize = 4;
        rule.medianAxis = BvhBuildRule::MedianAxis::NodeBox;
        rule.medianTieById = false;
        const BinaryBvh tree = buildBinaryBvh(std::move(items), rule);
        mNodes.resize(tree.nodes.size());
        for (size_t k = 0; k < tree.nodes.size(); ++k) {
            const BinaryBvhNode& from = tree.nodes[k];
            BvhNode& to = mNodes[k];
            to.box = {Vec2(from.box.lo), Vec2(from.box.hi)};
            if (from.count > 0) {
                to.first = int(from.first);
                to.count = int(from.count);
            } else {
                to.left = int(k + 1);  // the first child follows its parent
                to.right = int(from.first);
            }
        }
        mOrder.assign(tree.order.begin(), tree.order.end());
    }

    Nearest nearest(Vec2 p, const Segment* skip = nullptr) const {
        Nearest n;
        if (mNodes.empty()) return n;
        int stack[64];
        int top = 0;
        stack[top++] = 0;
        while (top > 0) {
            const BvhNode& node = mNodes[stack[--top]];
            if (boxDistance(node.box, p) >= n.d) continue;
            if (node.left < 0) {
                for (int i = 0; i < node.count; ++i) {
                    const Segment& seg = mSegments[mOrder[node.first + i]];
                    if (&seg != skip) nearestOn(seg, p, n);
                }
                continue;
            }
            const double dl = boxDistance(mNodes[node.left].box, p);
            const double dr = boxDistance(mNodes[node.right].box, p);
            // Push the farther child first so the nearer is visited first.
            stack[top++] = dl <= dr ? node.right : node.left;
            stack[top++] = dl <= dr ? node.left : node.right;
        }
        return n;
    }

    bool inside(Vec2 p) const {
        bool odd = false;
        for (const Piece& piece : mPieces) odd ^= crosses(piece, p);
        return odd;
    }

    std::vector<Segment> mSegments;  // not resized after construction: pieces point into it
    std::vector<Piece> mPieces;
    std::vector<BvhNode> mNodes;
    std::vector<int> mOrder;
    double mScale = 0.0;
};

}  // namespace

Bounds2 pathBounds(const PathShape& shape) {
    bool first = true;
    Bounds2 box;
    for (const PathLoop& loop : shape.loops) {
        for (const PathSegment& in : loop.segments) {
            std::vector<Vec2> points;
            if (in.kind == PathSegment::Kind::Arc) {
                const double r = glm::length(in.p[0] - in.p[2]);
                points = {in.p[2] - Vec2(r), in.p[2] + Vec2(r)};
            } else {
                const int n = in.kind == PathSegment::Kind::Line        ? 2
                              : in.kind == PathSegment::Kind::Quadratic ? 3
                                                                        : 4;
                points.assign(in.p.begin(), in.p.begin() + n);
            }
            for (const Vec2& q : points) {
                box.lo = first ? q : glm::min(box.lo, q);
                box.hi = first ? q : glm::max(box.hi, q);
                first = false;
            }
        }
    }
    return box;
}

std::shared_ptr<const ScalarField> pathField(PathShape shape) {
    return std::make_shared<const PathField>(shape);
}

}  // namespace kerf
