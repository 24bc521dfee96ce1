/// @file bench/reference/ref_scene.h
/// @brief The oracle's scene: a camera and objects, each a tree of closed-form primitives,
/// CSG operations and transforms, read from the `.ref` text that bench/gen_scenes.py writes
/// beside each .kerf and .pov (one node per line, children after their parent).
#pragma once

#include "real_vec.h"

#include <string>
#include <vector>

namespace kerf::bench {

struct RefNode {
    enum class Kind {
        Sphere,     // center, radius
        Box,        // lo, hi
        Cylinder,   // a, b, radius (capped)
        HalfSpace,  // normal . p <= offset
        Torus,      // around y: major, minor
        Union,
        Intersection,
        Difference,  // the first child minus the others
        Transform,   // child seen through worldFromLocal = linear * p + offset
    };
    Kind kind = Kind::Union;
    V3 a, b;              // centre / lo / from / normal; hi / to
    Real r1 = 0, r2 = 0;  // radius / offset / major; minor
    M3 localFromWorld;    // Transform: inverse of the linear part
    V3 offset;            // Transform: translation of worldFromLocal
    std::vector<RefNode> children;
};

struct RefCamera {
    V3 eye, lookAt, up;
    Real fovDegrees = 0;
};

struct RefScene {
    RefCamera camera;
    std::vector<RefNode> objects;
};

/// Parses a .ref file; throws std::runtime_error with the line number on bad input.
RefScene readRefScene(const std::string& path);

}  // namespace kerf::bench
