/// @file csg/profiles/profile.h
/// @brief 2-D profiles and the solids made from them: the API that `circle`, `rect`,
/// `polygon`, `path`, `offset`, `extrude` and `revolve` (lang/lower_profiles.cpp), text glyphs
/// and OpenSCAD's linear_extrude / rotate_extrude all use.
///
/// A Profile is a function d(u, v) written into an ExprGraph, negative inside, with a box
/// holding the region d ≤ 0. Circles, rectangles and paths (polygons, glyphs) give their exact
/// signed distance; Booleans are min / max of their operands (a bound of the distance, exact
/// in sign); offset(r) is d − r (exactly the rounded offset when d is a distance).
/// Extrude and revolve substitute (u, v) by functions of x, y, z and make an implicit leaf
/// (makeImplicit) with a tight bound, so they take part in CSG, slices, the octree and
/// `kerf check` like any implicit form.
#pragma once

#include "csg/profiles/profile_field.h"
#include "csg/tape/expr.h"
#include "csg/tree/node.h"

#include <functional>
#include <memory>
#include <vector>

namespace kerf {

/// A profile that is one plain outline: a straight extrusion of it is a closed-form solid
/// (a cylinder, a box, a prism: csg/profiles/prism.h) rather than an implicit one.
struct PlainOutline {
    enum class Kind : uint8_t { None, Circle, Rect, Path };
    Kind kind = Kind::None;
    Vec2 a{0.0}, b{0.0};  ///< Circle: the centre in a; Rect: lo in a, hi in b
    double radius = 0.0;
    PathShape path;  ///< Path: lines and Béziers (no arcs), filled even-odd
};

struct Profile {
    /// Writes d(u, v) into the graph and returns its node.
    std::function<ExprId(ExprGraph&, ExprId u, ExprId v)> distance;
    /// Holds every point with d ≤ 0.
    Bounds2 bounds;
    /// What the profile is, when it is one plain outline (Booleans and offsets are not).
    std::shared_ptr<const PlainOutline> plain;
};

/// The disc of the given centre and radius (radius > 0).
Profile profileCircle(Vec2 center, double radius);
/// The rectangle lo..hi (lo < hi on both axes).
Profile profileRect(Vec2 lo, Vec2 hi);
/// A filled path (even-odd), by csg/profiles/profile_field.h. An empty shape has no inside.
Profile profilePath(PathShape shape);
/// A closed polygon with holes, as a path of lines (each list at least three points).
Profile profilePolygon(const std::vector<Vec2>& outline,
                       const std::vector<std::vector<Vec2>>& holes);
/// min / max of the operands (at least one).
Profile profileUnion(std::vector<Profile> parts);
Profile profileIntersection(std::vector<Profile> parts);
/// The first minus all the others.
Profile profileDifference(std::vector<Profile> parts);
/// d − r: grown by r (r > 0, corners rounded) or shrunk by −r.
Profile profileOffset(Profile p, double r);

/// The affine map p ↦ A·p + t of the plane, A = [[m[0], m[1]], [m[3], m[4]]], t = (m[2], m[5])
/// (row-major 2×3), A invertible. The profile becomes σ_min(A)·d(A⁻¹(p − t)): the same zero set
/// and sign, and exactly the distance when A is rigid; otherwise a lower bound of it in
/// magnitude (|A·q − A·s| ≥ σ_min|q − s| for every point s), so it stays 1-Lipschitz and sound
/// to trace. Mirrors (det A < 0) are allowed.
Profile profileTransform(Profile p, const double m[6]);

struct ExtrudeOptions {
    double height = 1.0;  ///< along y, > 0
    double twist = 0.0;   ///< degrees turned (counter-clockwise seen from +y) from bottom to top
    /// The profile's size at the top relative to the bottom along its u and v axes, > 0.
    Vec2 scale{1.0, 1.0};
    bool center = false;  ///< y from −h/2 to h/2, else from 0 to h
};

/// The profile drawn in the (x, z) plane (u = x, v = z) swept along y.
NodePtr makeExtrude(const Profile& profile, const ExtrudeOptions& options);
/// The profile drawn in the (r, y) plane (u = distance from the y axis, v = y), turned about
/// the y axis by `degrees` in (0, 360], starting at +x toward +z. Only the part at u ≥ 0 counts.
NodePtr makeRevolve(const Profile& profile, double degrees = 360.0);

}  // namespace kerf
