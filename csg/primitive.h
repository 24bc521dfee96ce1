/// @file csg/primitive.h
/// @brief The common base of the leaves of a solid tree. Each primitive has a process-unique
/// id that its boundaries carry (for statistics and deterministic tie-breaks).
#pragma once

#include "csg/node.h"

namespace kerf {

uint32_t nextPrimitiveId();

class Primitive : public Node {
public:
    uint32_t id() const { return mId; }
    int primitiveCount() const override { return 1; }
    int depth() const override { return 1; }

protected:
    Primitive() : mId(nextPrimitiveId()) {}

    /// A boundary of this primitive at t with outward normal n (material left unset).
    Boundary boundary(double t, const Vec3& n) const {
        Boundary b;
        b.t = t;
        b.normal = n;
        b.primitive = mId;
        return b;
    }
    /// A boundary found by root isolation to the context's tolerance.
    Boundary rootBoundary(double t, const Vec3& n, const TraceContext& ctx) const {
        Boundary b = boundary(t, n);
        b.relError = static_cast<float>(ctx.relTolerance);
        return b;
    }

private:
    uint32_t mId;
};

}  // namespace kerf
