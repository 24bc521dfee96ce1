// The axis-aligned box: a slab test that knows which face each boundary lies on.
#include "csg/primitives/closed_primitive.h"
#include "csg/primitives/implicit_expr.h"
#include "csg/tree/solids.h"

#include <algorithm>

namespace kerf {
namespace {

class Box final : public ClosedFormPrimitive<Box> {
public:
    Box(const Vec3& lo, const Vec3& hi) { mBounds = {lo, hi}; }

    /// Max of the six slab distances: Lipschitz-1, exact distance inside and on the faces.
    double value(const Vec3& p) const override {
        const Vec3& lo = mBounds.lo;
        const Vec3& hi = mBounds.hi;
        const double x = std::max(lo.x - p.x, p.x - hi.x);
        const double y = std::max(lo.y - p.y, p.y - hi.y);
        const double z = std::max(lo.z - p.z, p.z - hi.z);
        return std::max(std::max(x, y), z);
    }

    long double valueExtended(const LVec3& p) const override {
        long double v = -INFINITY;
        for (int a = 0; a < 3; ++a)
            v = std::max({v, (long double)mBounds.lo[a] - p[a], p[a] - (long double)mBounds.hi[a]});
        return v;
    }

    Interval valueInterval(const IntervalVec3& b) const override {
        const Vec3& lo = mBounds.lo;
        const Vec3& hi = mBounds.hi;
        const Interval x = max(lo.x - b.x, b.x - hi.x);
        const Interval y = max(lo.y - b.y, b.y - hi.y);
        const Interval z = max(lo.z - b.z, b.z - hi.z);
        return max(max(x, y), z);
    }

    NodeKind kind() const override { return NodeKind::Box; }
    NodeParams params() const override { return BoxParams{mBounds.lo, mBounds.hi}; }

    ExprId implicitExpr(ExprGraph& g, ExprId x, ExprId y, ExprId z) const override {
        ExprBuilder e{g};
        const ExprId v[3] = {x, y, z};
        ExprId slab[3];
        for (int a = 0; a < 3; ++a)
            slab[a] = e.max(e.sub(e.c(mBounds.lo[a]), v[a]), e.sub(v[a], e.c(mBounds.hi[a])));
        return e.max(e.max(slab[0], slab[1]), slab[2]);
    }

private:
    friend class ClosedFormPrimitive<Box>;

    /// TraceMethod::Closed.
    void closedSpans(const Ray& ray, SpanList& out) const {
        const Vec3& lo = mBounds.lo;
        const Vec3& hi = mBounds.hi;
        // Slabs combined with min/max rather than data-dependent branches; the faces are
        // identified afterwards, for hits only.
        double tNear[3], tFar[3];
        for (int a = 0; a < 3; ++a) {
            const double o = ray.origin[a], d = ray.dir[a];
            if (d == 0.0) {
                // Parallel to this slab (+0 or −0): no 0·inf. The closed box holds its faces,
                // as Bounds3::clipRay does, so a ray lying in a face plane is inside.
                if (o < lo[a] || o > hi[a]) return;
                tNear[a] = -kInf;
                tFar[a] = kInf;
                continue;
            }
            const double inv = 1.0 / d;
            const double tLo = (lo[a] - o) * inv, tHi = (hi[a] - o) * inv;
            tNear[a] = d > 0.0 ? tLo : tHi;
            tFar[a] = d > 0.0 ? tHi : tLo;
        }
        const double tin = std::max(std::max(tNear[0], tNear[1]), tNear[2]);
        const double tout = std::min(std::min(tFar[0], tFar[1]), tFar[2]);
        // A touch of an edge or corner (tin == tout) is kept as a zero-width span: a Boolean
        // parent then sees this operand at the tie (so a union of abutting boxes enters through
        // the outer face, not the seam), and drops the sliver afterwards; alone it is no hit.
        if (!(tin <= tout)) return;
        // Entering through the face the ray runs into: the lo face when d > 0 (normal −e),
        // the hi face when d < 0 (normal +e); leaving is the opposite face.
        const int axisIn = tNear[0] == tin ? 0 : tNear[1] == tin ? 1 : 2;
        const int axisOut = tFar[0] == tout ? 0 : tFar[1] == tout ? 1 : 2;
        Vec3 nIn(0.0), nOut(0.0);
        nIn[axisIn] = ray.dir[axisIn] > 0.0 ? -1.0 : 1.0;
        nOut[axisOut] = ray.dir[axisOut] > 0.0 ? 1.0 : -1.0;
        out.push_back({boundary(tin, nIn), boundary(tout, nOut)});
    }
};

}  // namespace

NodePtr makeBox(const Vec3& lo, const Vec3& hi) { return std::make_shared<Box>(lo, hi); }

}  // namespace kerf
