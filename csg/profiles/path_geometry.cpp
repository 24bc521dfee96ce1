// The geometry of a path's segments: nearest points and crossings (csg/profiles/path_geometry.h).
#include "csg/profiles/path_geometry.h"

#include <algorithm>

namespace kerf::path_geometry {

void nearestOnAny(const Segment& s, Vec2 p, Nearest& n);
void nearestOnCubic(const Cubic& c, Vec2 p, double tolerance, double size, int depth, Nearest& n);

/// [0, 2π)
double wrapAngle(double a) {
    a = std::fmod(a, kTwoPi);
    return a < 0.0 ? a + kTwoPi : a;
}

/// The point of segment [a, b] nearest to p, and its parameter in [0, 1].
Vec2 nearestOnSegment(Vec2 a, Vec2 b, Vec2 p, double& s) {
    const Vec2 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    s = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return a + s * ab;
}

double distanceToSegment(Vec2 a, Vec2 b, Vec2 p) {
    double s;
    return glm::length(p - nearestOnSegment(a, b, p, s));
}

double boxDistance(const Bounds2& b, Vec2 p) {
    const Vec2 d = glm::max(glm::max(b.lo - p, p - b.hi), Vec2(0.0));
    return glm::length(d);
}

void nearestOnCubic(const Cubic& c, Vec2 p, double tolerance, double size, int depth, Nearest& n) {
    // The control polygon lies within h of the chord, so the curve does too.
    const double h = std::max(distanceToSegment(c.p[0], c.p[3], c.p[1]),
                              distanceToSegment(c.p[0], c.p[3], c.p[2]));
    double s;
    const double chord = glm::length(p - nearestOnSegment(c.p[0], c.p[3], p, s));
    const double lower = chord - h;
    if (lower >= n.d) return;
    const Vec2 q = c.at(s);
    n.offer(p, q, c.tangent(s), size);
    n.offer(p, c.p[0], c.tangent(0.0), size);
    n.offer(p, c.p[3], c.tangent(1.0), size);
    if (depth >= 52 || glm::length(p - q) - lower <= tolerance) return;
    const auto [left, right] = c.split(0.5);
    // Nearer half first, so the bound prunes the other.
    const double dl = distanceToSegment(left.p[0], left.p[3], p);
    const double dr = distanceToSegment(right.p[0], right.p[3], p);
    if (dl <= dr) {
        nearestOnCubic(left, p, tolerance, size, depth + 1, n);
        nearestOnCubic(right, p, tolerance, size, depth + 1, n);
    } else {
        nearestOnCubic(right, p, tolerance, size, depth + 1, n);
        nearestOnCubic(left, p, tolerance, size, depth + 1, n);
    }
}

void nearestOn(const Segment& s, Vec2 p, Nearest& n) {
    const double before = n.d;
    nearestOnAny(s, p, n);
    if (n.d < before) n.segment = &s;
}

void nearestOnAny(const Segment& s, Vec2 p, Nearest& n) {
    const double size = glm::length(s.box.hi - s.box.lo);
    switch (s.kind) {
        case PathSegment::Kind::Line: {
            double t;
            n.offer(p, nearestOnSegment(s.a, s.b, p, t), s.b - s.a, size);
            return;
        }
        case PathSegment::Kind::Arc: {
            const Vec2 d = p - s.arc.c;
            const double len = glm::length(d);
            const auto tangentAt = [&](Vec2 q) {
                const Vec2 r = q - s.arc.c;
                return Vec2(-r.y, r.x);
            };
            if (len > 0.0 && s.arc.covers(std::atan2(d.y, d.x))) {
                const Vec2 q = s.arc.c + d * (s.arc.r / len);
                n.offer(p, q, tangentAt(q), size);
            }
            n.offer(p, s.a, tangentAt(s.a), size);
            n.offer(p, s.b, tangentAt(s.b), size);
            return;
        }
        default: nearestOnCubic(s.cubic, p, s.tolerance, size, 0, n);
    }
}

/// Does the ray from p toward +x cross the piece? Half-open in y: a piece counts when
/// a.y ≤ p.y < b.y or b.y ≤ p.y < a.y, so a join between two pieces counts once.
bool crosses(const Piece& piece, Vec2 p) {
    const bool up = piece.a.y <= p.y && p.y < piece.b.y;
    const bool down = piece.b.y <= p.y && p.y < piece.a.y;
    if (!up && !down) return false;
    if (piece.xMax <= p.x) return false;
    if (piece.xMin > p.x && piece.seg->kind != PathSegment::Kind::Arc) return true;
    switch (piece.seg->kind) {
        case PathSegment::Kind::Line: {
            const double t = (p.y - piece.a.y) / (piece.b.y - piece.a.y);
            return piece.a.x + t * (piece.b.x - piece.a.x) > p.x;
        }
        case PathSegment::Kind::Arc: {
            const Arc& arc = piece.seg->arc;
            const double dy = p.y - arc.c.y;
            const double half = std::sqrt(std::max(0.0, arc.r * arc.r - dy * dy));
            return (piece.rightHalf ? arc.c.x + half : arc.c.x - half) > p.x;
        }
        default: {  // bisection on the monotone y(t)
            double lo = 0.0, hi = 1.0;
            const bool rising = piece.b.y > piece.a.y;
            for (int i = 0; i < 60 && hi - lo > 0.0; ++i) {
                const double mid = 0.5 * (lo + hi);
                if ((piece.cubic.at(mid).y < p.y) == rising)
                    lo = mid;
                else
                    hi = mid;
            }
            return piece.cubic.at(0.5 * (lo + hi)).x > p.x;
        }
    }
}

/// Roots of a t² + b t + c in (0, 1), ascending.
std::vector<double> unitRoots(double a, double b, double c) {
    std::vector<double> roots;
    const double scale = std::max({std::abs(a), std::abs(b), std::abs(c)});
    if (scale == 0.0) return roots;
    if (std::abs(a) <= 0x1p-40 * scale) {
        if (b != 0.0) roots.push_back(-c / b);
    } else {
        const double disc = b * b - 4.0 * a * c;
        if (disc >= 0.0) {
            const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
            roots.push_back(q / a);
            if (q != 0.0) roots.push_back(c / q);
        }
    }
    std::vector<double> inside;
    for (double t : roots)
        if (t > 0.0 && t < 1.0) inside.push_back(t);
    std::sort(inside.begin(), inside.end());
    return inside;
}

}  // namespace kerf::path_geometry
