// The linear prism: closed-form spans of a polygon extruded along y (csg/prism.h).
#include "csg/prism.h"

#include "csg/closed_primitive.h"

#include <algorithm>
#include <utility>

namespace kerf {

namespace {

class Prism final : public ClosedFormPrimitive<Prism> {
public:
    Prism(std::vector<std::vector<Vec2>> loops, double y0, double y1, NodePtr implicitForm)
        : mLoops(std::move(loops)), mY0(y0), mY1(y1), mImplicit(std::move(implicitForm)),
          mForm(static_cast<const Primitive&>(*mImplicit)) {
        mBounds = mImplicit->bounds();
    }

    double value(const Vec3& p) const override { return mImplicit->value(p); }
    long double valueExtended(const LVec3& p) const override { return mImplicit->valueExtended(p); }
    Interval valueInterval(const IntervalVec3& box) const override { return mImplicit->valueInterval(box); }
    NodeKind kind() const override { return mImplicit->kind(); }
    NodeParams params() const override { return mImplicit->params(); }
    ExprId implicitExpr(ExprGraph& g, ExprId x, ExprId y, ExprId z) const override {
        return mForm.implicitExpr(g, x, y, z);
    }
    const Tape* compiledForm() const override { return mForm.compiledForm(); }
    double lipschitz() const override { return mForm.lipschitz(); }

private:
    friend class ClosedFormPrimitive<Prism>;

    struct Crossing {
        double t;
        Vec2 normal;  ///< the edge's normal, either side (unit)
    };

    /// Even-odd inside test of a point of the plane: crossings of the ray toward +x.
    bool inside(Vec2 p) const {
        bool odd = false;
        for (const auto& loop : mLoops) {
            for (size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
                const Vec2 a = loop[j], b = loop[i];
                if ((a.y <= p.y) != (b.y <= p.y)) {
                    const double x = a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x);
                    odd ^= x > p.x;
                }
            }
        }
        return odd;
    }

    void closedSpans(const Ray& ray, SpanList& out) const {
        // The slab y0 ≤ y ≤ y1 (closed, as a box's).
        double ta = -kInf, tb = kInf;
        if (ray.dir.y == 0.0) {
            if (ray.origin.y < mY0 || ray.origin.y > mY1) return;
        } else {
            const double t0 = (mY0 - ray.origin.y) / ray.dir.y, t1 = (mY1 - ray.origin.y) / ray.dir.y;
            ta = std::min(t0, t1);
            tb = std::max(t0, t1);
        }
        const Vec3 capIn(0.0, ray.dir.y > 0.0 ? -1.0 : 1.0, 0.0);
        const Vec3 capOut = -capIn;
        const Vec2 o(ray.origin.x, ray.origin.z), d(ray.dir.x, ray.dir.z);
        if (d.x == 0.0 && d.y == 0.0) {  // along y: in or out of the polygon throughout
            if (inside(o)) out.push_back({boundary(ta, capIn), boundary(tb, capOut)});
            return;
        }
        // The shadow of the ray is the line o + t·d of the plane. An edge crosses it where the
        // side s = d × (q − o) of its ends differs; each vertex's side is computed once per
        // loop, so an edge through a vertex is counted by exactly one of the two edges there
        // (the half-open rule s ≤ 0 / s > 0), and a touch is counted by none or both.
        std::vector<Crossing>& hits = mScratch;
        hits.clear();
        const double dd = glm::dot(d, d);
        for (const auto& loop : mLoops) {
            const size_t n = loop.size();
            double sPrev = d.x * (loop[n - 1].y - o.y) - d.y * (loop[n - 1].x - o.x);
            for (size_t i = 0; i < n; ++i) {
                const Vec2 a = loop[i == 0 ? n - 1 : i - 1], b = loop[i];
                const double s = d.x * (b.y - o.y) - d.y * (b.x - o.x);
                if ((sPrev <= 0.0) != (s <= 0.0)) {
                    // At a vertex on the line, the vertex itself: both edges there give one t.
                    const Vec2 q = s == 0.0 ? b : sPrev == 0.0 ? a : a + sPrev / (sPrev - s) * (b - a);
                    const Vec2 e = b - a;
                    hits.push_back({glm::dot(q - o, d) / dd, Vec2(-e.y, e.x) / glm::length(e)});
                }
                sPrev = s;
            }
        }
        std::sort(hits.begin(), hits.end(), [](const Crossing& x, const Crossing& y) { return x.t < y.t; });
        // The line starts and ends outside: crossings pair up into inside intervals.
        for (size_t k = 0; k + 1 < hits.size(); k += 2) {
            const double tin = std::max(hits[k].t, ta), tout = std::min(hits[k + 1].t, tb);
            if (!(tin <= tout)) continue;
            const auto side = [&](const Crossing& c, bool entering) {
                const Vec2 n = (glm::dot(c.normal, d) < 0.0) == entering ? c.normal : -c.normal;
                return Vec3(n.x, 0.0, n.y);
            };
            const Boundary leave =
                hits[k + 1].t <= tb ? boundary(tout, side(hits[k + 1], false)) : boundary(tout, capOut);
            // A line through a vertex where the outline touches it from outside (a reflex
            // vertex met from inside) leaves and enters at one t: one span, no gap.
            if (!out.empty() && out.back().out.t == tin) {
                out.back().out = leave;
                continue;
            }
            out.push_back({hits[k].t >= ta ? boundary(tin, side(hits[k], true)) : boundary(tin, capIn), leave});
        }
    }

    std::vector<std::vector<Vec2>> mLoops;
    double mY0, mY1;
    NodePtr mImplicit;
    const Primitive& mForm;
    static thread_local std::vector<Crossing> mScratch;
};

thread_local std::vector<Prism::Crossing> Prism::mScratch;

}  // namespace

NodePtr makePrism(std::vector<std::vector<Vec2>> loops, double y0, double y1, NodePtr implicitForm) {
    return std::make_shared<Prism>(std::move(loops), y0, y1, std::move(implicitForm));
}

}  // namespace kerf
