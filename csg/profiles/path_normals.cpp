// Normal sectors of curved path segments near a point (csg/profiles/path_normals.h).
#include "csg/profiles/path_normals.h"

#include <algorithm>
#include <cmath>

namespace kerf::path_geometry {

namespace {

constexpr double kPi = 0.5 * kTwoPi;

Bounds2 controlBox(const Cubic& c) {
    Bounds2 box{c.p[0], c.p[0]};
    for (const Vec2& q : c.p) {
        box.lo = glm::min(box.lo, q);
        box.hi = glm::max(box.hi, q);
    }
    return box;
}

double farthestCorner(const Bounds2& b, Vec2 c) {
    const Vec2 d = glm::max(glm::abs(b.lo - c), glm::abs(b.hi - c));
    return glm::length(d);
}

/// The parameter hull [lo, hi] of the pieces of `piece` (covering [t0, t1] of the whole
/// curve) whose control boxes come within `reach` of c; pieces are split until they are
/// small beside the reach.
void nearHull(const Cubic& piece, double t0, double t1, Vec2 c, double reach, int depth, double& lo,
              double& hi) {
    const Bounds2 box = controlBox(piece);
    if (boxDistance(box, c) > reach) return;
    if (depth >= 48 || glm::length(box.hi - box.lo) <= 0.25 * reach) {
        lo = std::min(lo, t0);
        hi = std::max(hi, t1);
        return;
    }
    const auto [left, right] = piece.split(0.5);
    const double tm = 0.5 * (t0 + t1);
    nearHull(left, t0, tm, c, reach, depth + 1, lo, hi);
    nearHull(right, tm, t1, c, reach, depth + 1, lo, hi);
}

/// The sector of tangent directions of a cubic: its derivative is a quadratic Bézier on the
/// control polygon's legs, so every tangent lies in the cone of the three legs. The angles
/// are padded by the rounding of legs computed from coordinates of size `scale`.
bool tangentSector(const Cubic& c, double scale, double& lo, double& hi) {
    const Vec2 legs[3] = {c.p[1] - c.p[0], c.p[2] - c.p[1], c.p[3] - c.p[2]};
    double shortest = kInf;
    for (const Vec2& h : legs) shortest = std::min(shortest, glm::length(h));
    if (!(shortest > 0.0)) return false;
    double a[3] = {0.0, 0.0, 0.0};
    for (int i = 1; i < 3; ++i)
        a[i] =
            std::atan2(legs[0].x * legs[i].y - legs[0].y * legs[i].x, glm::dot(legs[0], legs[i]));
    const double base = std::atan2(legs[0].y, legs[0].x);
    // Each leg's direction is off by its components' rounding (a few ulps of `scale`) over
    // its length; atan2 adds a few ulps of π.
    const double pad = 64.0 * 0x1p-53 * scale / shortest + 0x1p-40;
    lo = base + std::min({a[0], a[1], a[2]}) - pad;
    hi = base + std::max({a[0], a[1], a[2]}) + pad;
    return hi - lo < kPi;
}

bool cubicSector(const Segment& s, Vec2 c, double reach, NormalSector& sector, double& clear) {
    double lo = 2.0, hi = -1.0;
    nearHull(s.cubic, 0.0, 1.0, c, reach, 0, lo, hi);
    if (!(lo > 0.0 && hi < 1.0 && lo < hi)) return false;  // none in reach, or an end is
    const double scale = farthestCorner(s.box, Vec2(0.0));
    const Cubic part = s.cubic.part(lo, hi);
    double tlo, thi;
    if (!tangentSector(part, scale, tlo, thi)) return false;
    sector.partBox = controlBox(part);
    clear = farthestCorner(sector.partBox, c);
    // The rest of the curve must stay out of the disc of radius `clear`: the pieces that
    // enter it must form one part that turns by less than π (so it does not cross itself).
    double lo2 = 2.0, hi2 = -1.0;
    nearHull(s.cubic, 0.0, 1.0, c, clear, 0, lo2, hi2);
    if (!(lo2 > 0.0 && hi2 < 1.0)) return false;
    double wlo, whi;
    if (!tangentSector(s.cubic.part(lo2, hi2), scale, wlo, whi)) return false;
    sector.lo = tlo + 0.5 * kPi;
    sector.hi = thi + 0.5 * kPi;
    return true;
}

bool arcSector(const Segment& s, Vec2 c, double reach, NormalSector& sector, double& clear) {
    const Arc& arc = s.arc;
    const Vec2 off = c - arc.c;
    const double dc = glm::length(off);
    if (!(dc > 2.0 * reach) || !(arc.r > 0.0)) return false;
    // The circle's points within reach of c lie within this angle of the direction to c.
    const double half = std::asin(std::min(1.0, reach / dc)) * (1.0 + 0x1p-40) + 0x1p-40;
    const double phi = std::atan2(off.y, off.x);
    // That part must lie inside the arc, away from its ends.
    if (!arc.covers(phi) || glm::length(s.a - c) <= reach || glm::length(s.b - c) <= reach)
        return false;
    // The normals Nearest reports for arcs point to the centre, whichever way they turn.
    sector.lo = phi - half + kPi;
    sector.hi = phi + half + kPi;
    sector.partBox = {c - Vec2(reach), c + Vec2(reach)};
    clear = reach;
    return true;
}

/// Bounds of cos over [lo, hi] (hi − lo < 2π).
Interval cosRange(double lo, double hi) {
    double a = std::cos(lo), b = std::cos(hi);
    Interval r(std::min(a, b), std::max(a, b));
    // Extremes where the sector passes an angle 2πk (max 1) or π + 2πk (min −1).
    const double kMax = std::ceil(lo / kTwoPi) * kTwoPi;
    if (kMax <= hi) r.hi = 1.0;
    const double kMin = std::ceil((lo - kPi) / kTwoPi) * kTwoPi + kPi;
    if (kMin <= hi) r.lo = -1.0;
    return r;
}

}  // namespace

bool nearNormalSector(const Segment& s, Vec2 c, double reach, NormalSector& sector, double& clear) {
    if (!(reach > 0.0) || !std::isfinite(reach)) return false;
    switch (s.kind) {
        case PathSegment::Kind::Quadratic:
        case PathSegment::Kind::Cubic: return cubicSector(s, c, reach, sector, clear);
        case PathSegment::Kind::Arc: return arcSector(s, c, reach, sector, clear);
        case PathSegment::Kind::Line: return false;
    }
    return false;
}

void sectorBox(double lo, double hi, Interval& x, Interval& y) {
    constexpr double kUlps = 0x1p-46;  // cos, sin and the angles' rounding
    const Interval cx = cosRange(lo, hi);
    const Interval sy = cosRange(lo - 0.5 * kPi, hi - 0.5 * kPi);  // sin θ = cos(θ − π/2)
    x = Interval(std::max(-1.0, cx.lo - kUlps), std::min(1.0, cx.hi + kUlps));
    y = Interval(std::max(-1.0, sy.lo - kUlps), std::min(1.0, sy.hi + kUlps));
}

}  // namespace kerf::path_geometry
