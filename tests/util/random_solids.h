/// @file tests/util/random_solids.h
/// @brief Seeded random primitives of every kind and random rays through them, for property
/// tests over mixes of solids (order invariance, membership).
#pragma once

#include "util/oracles.h"

#include <cmath>
#include <memory>

namespace kerf::test {

/// The primitive kinds randomPrimitive draws from.
enum class PrimitiveKind {
    Sphere,
    Box,
    GridBox,
    Cylinder,
    Cone,
    Torus,
    HalfSpace,
    ImplicitSphere,
    ImplicitFull,
    Count
};

/// A random primitive of the given kind in about [-1.5, 1.5]³. Implicit spheres get a bound
/// box that cuts them on some sides; ImplicitFull (f = −1) is nothing but its bound box, whose
/// faces are all the implicit's own boundaries. Half-spaces are axis-aligned half the time, so
/// their bounds clip rays too. GridBoxes have their faces on a grid of halves, so two of them
/// often share a face plane: crossings of different primitives at exactly the same t.
inline NodePtr randomPrimitive(Random& rnd, PrimitiveKind kind) {
    auto point = [&](double r) {
        return Vec3(rnd.uniform(-r, r), rnd.uniform(-r, r), rnd.uniform(-r, r));
    };
    switch (kind) {
        case PrimitiveKind::Sphere: return makeSphere(point(1.0), rnd.uniform(0.3, 1.0));
        case PrimitiveKind::Box: {
            const Vec3 c = point(1.0),
                       h(rnd.uniform(0.2, 1.0), rnd.uniform(0.2, 1.0), rnd.uniform(0.2, 1.0));
            return makeBox(c - h, c + h);
        }
        case PrimitiveKind::GridBox: {
            Vec3 lo, hi;
            for (int a = 0; a < 3; ++a) {
                lo[a] = 0.5 * std::floor(rnd.uniform(-3.0, 3.0));
                hi[a] = lo[a] + 0.5 * (1.0 + std::floor(rnd.uniform(0.0, 3.0)));
            }
            return makeBox(lo, hi);
        }
        case PrimitiveKind::Cylinder: {
            const Vec3 a = point(1.0);
            return makeCylinder(a, a + rnd.uniform(0.5, 1.5) * rnd.unitVector(),
                                rnd.uniform(0.2, 0.7));
        }
        case PrimitiveKind::Cone: {
            const Vec3 a = point(1.0);
            const double r2 = rnd.uniform(0.0, 1.0) < 0.3 ? 0.0 : rnd.uniform(0.1, 0.5);
            return makeCone(a, a + rnd.uniform(0.5, 1.5) * rnd.unitVector(), rnd.uniform(0.2, 0.8),
                            r2);
        }
        case PrimitiveKind::Torus: {
            const double major = rnd.uniform(0.4, 1.0);
            const Affine place =
                Affine::translate(point(0.8)).after(Affine::rotateDegrees(point(180.0)));
            return makeTransform(makeTorus(major, rnd.uniform(0.1, 0.8) * major), place);
        }
        case PrimitiveKind::HalfSpace: {
            Vec3 n = rnd.unitVector();
            if (rnd.uniform(0.0, 1.0) < 0.5) {
                n = Vec3(0.0);
                n[int(rnd.uniform(0.0, 3.0)) % 3] = rnd.uniform(0.0, 1.0) < 0.5 ? -1.0 : 1.0;
            }
            return makeHalfSpace(n, rnd.uniform(-0.8, 0.8));
        }
        case PrimitiveKind::ImplicitSphere:
        case PrimitiveKind::ImplicitFull: {
            ExprGraph g;
            const double r = rnd.uniform(0.5, 1.2);
            const bool full = kind == PrimitiveKind::ImplicitFull;
            const ExprId f = full ? g.constant(-1.0) : sphereExpr(g, r);
            // A box around the sphere's centre that cuts it on the sides where it is short.
            Vec3 lo, hi;
            for (int a = 0; a < 3; ++a) {
                lo[a] = -rnd.uniform(0.3, 1.5) * r;
                hi[a] = rnd.uniform(0.3, 1.5) * r;
            }
            const Vec3 c = point(0.8);
            return makeTransform(makeImplicit(Tape::compile(g, f), {lo, hi}), Affine::translate(c));
        }
        case PrimitiveKind::Count: break;
    }
    return nullptr;
}

inline PrimitiveKind randomKind(Random& rnd) {
    return PrimitiveKind(int(rnd.uniform(0.0, double(PrimitiveKind::Count))) %
                         int(PrimitiveKind::Count));
}

/// A random ray whose origin lies in [-2.5, 2.5]³ (often inside a solid) and whose direction
/// has, a quarter of the time, one or two components +0 or −0 (rays parallel to faces and
/// slabs, where a −0 must act as +0).
inline Ray randomRayWithZeros(Random& rnd) {
    const Vec3 o(rnd.uniform(-2.5, 2.5), rnd.uniform(-2.5, 2.5), rnd.uniform(-2.5, 2.5));
    Vec3 d = rnd.unitVector();
    if (rnd.uniform(0.0, 1.0) < 0.25) {
        const int zeros = rnd.uniform(0.0, 1.0) < 0.7 ? 1 : 2;
        const int first = int(rnd.uniform(0.0, 3.0)) % 3;
        for (int k = 0; k < zeros; ++k)
            d[(first + k) % 3] = rnd.uniform(0.0, 1.0) < 0.5 ? 0.0 : -0.0;
    }
    return {o, d};
}

}  // namespace kerf::test
