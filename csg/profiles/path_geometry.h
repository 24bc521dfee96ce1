/// @file csg/profiles/path_geometry.h
/// @brief The geometry of a path's segments for its distance field
/// (csg/profiles/profile_field.cpp): lines, circular arcs and cubic Béziers (quadratics raised),
/// the nearest point on each (a Bézier by subdivision with a certified lower bound), and crossing
/// counts over y-monotone pieces. Internal to csg/.
#pragma once

#include "csg/profiles/profile_field.h"
#include "csg/profiles/profile_path.h"

#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace kerf::path_geometry {

/// [0, 2π)
double wrapAngle(double a);
/// The point of segment [a, b] nearest to p, and its parameter in [0, 1].
Vec2 nearestOnSegment(Vec2 a, Vec2 b, Vec2 p, double& s);
double distanceToSegment(Vec2 a, Vec2 b, Vec2 p);

inline constexpr double kTwoPi = 6.283185307179586476925286766559;
/// Béziers are refined until bound and found point agree to this fraction of their size.
inline constexpr double kCurveTolerance = 0x1p-34;

struct Cubic {
    std::array<Vec2, 4> p;
    Vec2 at(double t) const {
        const double u = 1.0 - t;
        return u * u * u * p[0] + 3.0 * u * u * t * p[1] + 3.0 * u * t * t * p[2] +
               t * t * t * p[3];
    }
    /// The direction of travel at t (the chord where the derivative vanishes).
    Vec2 tangent(double t) const {
        const double u = 1.0 - t;
        const Vec2 d = u * u * (p[1] - p[0]) + 2.0 * u * t * (p[2] - p[1]) + t * t * (p[3] - p[2]);
        return d != Vec2(0.0) ? d : p[3] - p[0];
    }
    /// de Casteljau at t: the part before t and after it.
    std::pair<Cubic, Cubic> split(double t) const {
        const Vec2 a = glm::mix(p[0], p[1], t), b = glm::mix(p[1], p[2], t),
                   c = glm::mix(p[2], p[3], t);
        const Vec2 d = glm::mix(a, b, t), e = glm::mix(b, c, t);
        const Vec2 m = glm::mix(d, e, t);
        return {Cubic{{p[0], a, d, m}}, Cubic{{m, e, c, p[3]}}};
    }
    /// The part over [t0, t1].
    Cubic part(double t0, double t1) const {
        Cubic right = t0 > 0.0 ? split(t0).second : *this;
        if (t1 >= 1.0) return right;
        return right.split((t1 - t0) / (1.0 - t0)).first;
    }
};

/// A circular arc by centre, radius, start angle and signed sweep (positive counter-clockwise).
struct Arc {
    Vec2 c;
    double r = 0.0;
    double theta0 = 0.0;
    double sweep = 0.0;
    bool covers(double phi) const {
        const double s = sweep > 0.0 ? wrapAngle(phi - theta0) : wrapAngle(theta0 - phi);
        return s <= std::abs(sweep);
    }
    Vec2 at(double theta) const { return c + r * Vec2(std::cos(theta), std::sin(theta)); }
};

struct Segment {
    PathSegment::Kind kind = PathSegment::Kind::Line;
    Vec2 a, b;  ///< the end points as written (joins compare equal)
    Arc arc;
    Cubic cubic;  ///< quadratics are raised to cubics
    Bounds2 box;
    double tolerance = 0.0;  ///< absolute, for Béziers
};

/// A y-monotone piece of a segment, for crossing counts.
struct Piece {
    const Segment* seg = nullptr;
    Vec2 a, b;  ///< end points (the written ones at the segment's ends)
    double xMin, xMax;
    Cubic cubic;            ///< the Bézier piece
    bool rightHalf = true;  ///< the arc piece lies at x ≥ centre
};

/// The nearest point found so far, with the unit normal of its segment there (either side)
/// and the segment's size: near the outline p − q is rounding noise, the normal is not.
struct Nearest {
    double d = kInf;
    Vec2 q{0.0};
    Vec2 normal{0.0};
    double size = 0.0;
    const Segment* segment = nullptr;
    void offer(Vec2 p, Vec2 point, Vec2 tangent, double segmentSize) {
        const double dist = glm::length(p - point);
        if (dist < d) {
            d = dist;
            q = point;
            const double len = glm::length(tangent);
            normal = len > 0.0 ? Vec2(-tangent.y, tangent.x) / len : Vec2(0.0);
            size = segmentSize;
        }
    }
};

/// The distance from p to a box (0 inside it).
double boxDistance(const Bounds2& b, Vec2 p);
/// Offers the segment's point nearest to p to n (recording the segment when it is nearer).
void nearestOn(const Segment& s, Vec2 p, Nearest& n);
/// Does the ray from p toward +x cross the piece? Half-open in y: a piece counts when
/// a.y ≤ p.y < b.y or b.y ≤ p.y < a.y, so a join between two pieces counts once.
bool crosses(const Piece& piece, Vec2 p);
/// Roots of a t² + b t + c in (0, 1), ascending.
std::vector<double> unitRoots(double a, double b, double c);

}  // namespace kerf::path_geometry
