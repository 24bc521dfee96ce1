// Overlap of two outlines by recursive subdivision: two Bézier pieces can meet only where
// their control polygons' boxes meet (a Bézier lies in its control points' convex hull), so
// pairs whose boxes are apart are dropped and the others split in halves until the boxes are
// apart or tiny. Boxes are widened by a few ulps of the outline's size, so rounding in the
// splits cannot make two touching curves look apart.

#include "io/outline_overlap.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "io/font_outline.h"

namespace kerf {
namespace {

// A Bézier of degree 1..3 as its control points (lines are degree 1).
struct Piece {
    int n = 0;  // number of control points
    Vec2 p[4];
};

Piece pieceOf(const PathSegment& s) {
    Piece c;
    c.n = s.kind == PathSegment::Kind::Line        ? 2
          : s.kind == PathSegment::Kind::Quadratic ? 3
          : s.kind == PathSegment::Kind::Cubic     ? 4
                                                   : 0;
    for (int i = 0; i < c.n; ++i) c.p[i] = s.p[i];
    return c;
}

struct Box {
    Vec2 lo, hi;
};

Box boxOf(const Piece& c, double pad) {
    Box b{c.p[0], c.p[0]};
    for (int i = 1; i < c.n; ++i) {
        b.lo = glm::min(b.lo, c.p[i]);
        b.hi = glm::max(b.hi, c.p[i]);
    }
    b.lo -= Vec2(pad);
    b.hi += Vec2(pad);
    return b;
}

bool meet(const Box& a, const Box& b) {
    return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y;
}

// De Casteljau at t = ½.
void split(const Piece& c, Piece& left, Piece& right) {
    Vec2 w[4];
    for (int i = 0; i < c.n; ++i) w[i] = c.p[i];
    left.n = right.n = c.n;
    for (int level = 0; level < c.n; ++level) {
        left.p[level] = w[0];
        right.p[c.n - 1 - level] = w[c.n - 1 - level];
        for (int i = 0; i + 1 < c.n - level; ++i) w[i] = 0.5 * (w[i] + w[i + 1]);
    }
}

// True when the pieces may meet. `tiny`: a box this small on both sides counts as a meeting.
bool piecesMeet(const Piece& a, const Piece& b, double pad, double tiny, int depth) {
    const Box ba = boxOf(a, pad), bb = boxOf(b, pad);
    if (!meet(ba, bb)) return false;
    const double sa = std::max(ba.hi.x - ba.lo.x, ba.hi.y - ba.lo.y);
    const double sb = std::max(bb.hi.x - bb.lo.x, bb.hi.y - bb.lo.y);
    if ((sa <= tiny && sb <= tiny) || depth >= 60) return true;
    Piece a0, a1, b0, b1;
    if (sa >= sb) {
        split(a, a0, a1);
        return piecesMeet(a0, b, pad, tiny, depth + 1) || piecesMeet(a1, b, pad, tiny, depth + 1);
    }
    split(b, b0, b1);
    return piecesMeet(a, b0, pad, tiny, depth + 1) || piecesMeet(a, b1, pad, tiny, depth + 1);
}

Vec2 pointAt(const Piece& c, double t) {
    Vec2 w[4];
    for (int i = 0; i < c.n; ++i) w[i] = c.p[i];
    for (int level = 1; level < c.n; ++level) {
        for (int i = 0; i + level < c.n; ++i) w[i] = (1.0 - t) * w[i] + t * w[i + 1];
    }
    return w[0];
}

// Parameters in (0, 1) where y'(t) = 0, with 0 and 1, sorted: y is monotone between them.
std::vector<double> yBreaks(const Piece& c) {
    std::vector<double> t{0.0, 1.0};
    auto keep = [&](double r) {
        if (r > 0.0 && r < 1.0) t.push_back(r);
    };
    if (c.n == 3) {
        const double d = c.p[0].y - 2.0 * c.p[1].y + c.p[2].y;
        if (d != 0.0) keep((c.p[0].y - c.p[1].y) / d);
    } else if (c.n == 4) {
        const double a = -c.p[0].y + 3.0 * c.p[1].y - 3.0 * c.p[2].y + c.p[3].y;
        const double b = 2.0 * (c.p[0].y - 2.0 * c.p[1].y + c.p[2].y), k = c.p[1].y - c.p[0].y;
        if (a == 0.0) {
            if (b != 0.0) keep(-k / b);
        } else if (const double disc = b * b - 4.0 * a * k; disc >= 0.0) {
            keep((-b - std::sqrt(disc)) / (2.0 * a));
            keep((-b + std::sqrt(disc)) / (2.0 * a));
        }
    }
    std::sort(t.begin(), t.end());
    return t;
}

double extent(const PathShape& s) {
    double e = 0.0;
    for (const auto& loop : s.loops) {
        for (const auto& seg : loop.segments) {
            for (const Vec2& p : seg.p) e = std::max({e, std::abs(p.x), std::abs(p.y)});
        }
    }
    return e;
}

}  // namespace

bool insideEvenOdd(const PathShape& shape, Vec2 q) {
    int crossings = 0;
    for (const auto& loop : shape.loops) {
        for (const auto& seg : loop.segments) {
            const Piece c = pieceOf(seg);
            if (c.n == 0) continue;
            const std::vector<double> br = yBreaks(c);
            for (size_t i = 0; i + 1 < br.size(); ++i) {
                double t0 = br[i], t1 = br[i + 1];
                const double y0 = pointAt(c, t0).y, y1 = pointAt(c, t1).y;
                if (y0 == y1) continue;
                const bool up = y0 < y1;
                // Half-open in y, so a join of two pieces counts once.
                if (!(up ? (y0 <= q.y && q.y < y1) : (y1 <= q.y && q.y < y0))) continue;
                for (int k = 0; k < 64 && t0 < t1; ++k) {
                    const double tm = 0.5 * (t0 + t1);
                    if ((pointAt(c, tm).y <= q.y) == up)
                        t0 = tm;
                    else
                        t1 = tm;
                }
                if (pointAt(c, 0.5 * (t0 + t1)).x > q.x) ++crossings;
            }
        }
    }
    return crossings % 2 == 1;
}

bool outlinesMayOverlap(const PathShape& a, const PathShape& b) {
    const double size = std::max(extent(a), extent(b));
    const double pad = 64.0 * std::numeric_limits<double>::epsilon() * size;
    const double tiny = 1e-9 * size;
    for (const auto& la : a.loops) {
        for (const auto& sa : la.segments) {
            const Piece pa = pieceOf(sa);
            for (const auto& lb : b.loops) {
                for (const auto& sb : lb.segments) {
                    const Piece pb = pieceOf(sb);
                    if (pa.n == 0 || pb.n == 0) {  // an arc: its exact bounds only
                        const InkBounds ba = segmentBounds(sa), bb = segmentBounds(sb);
                        if (meet({ba.lo, ba.hi}, {bb.lo, bb.hi})) return true;
                        continue;
                    }
                    if (piecesMeet(pa, pb, pad, tiny, 0)) return true;
                }
            }
        }
    }
    // No outlines meet: the regions share a point only if a whole loop of one is inside the
    // other.
    for (const auto& loop : a.loops) {
        if (!loop.segments.empty() && insideEvenOdd(b, loop.segments[0].start())) return true;
    }
    for (const auto& loop : b.loops) {
        if (!loop.segments.empty() && insideEvenOdd(a, loop.segments[0].start())) return true;
    }
    return false;
}

}  // namespace kerf
