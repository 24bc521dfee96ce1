// The moving node: a child turned and moved with the scene time (csg/tree/motion.h).
#include "csg/tree/motion.h"

#include "csg/tree/solids.h"

#include <algorithm>
#include <cmath>

namespace kerf {

namespace {

thread_local double tCurrentTime = 0.0;

/// The child at scene time s: turned by spin·s (as `rotate`: a rigid map, so t and lengths are
/// the same in both spaces) and then moved by velocity·s. Its bounds and interval values cover
/// every s in [0, 1], so a BVH, an octree or a beam built once classifies it soundly.
class MotionNode final : public Node {
public:
    MotionNode(NodePtr child, const Vec3& velocity, const Vec3& spin)
        : mChild(std::move(child)), mVelocity(velocity), mSpin(spin) {
        const Bounds3& b = mChild->bounds();
        Bounds3 swept = b;
        if (mSpin != Vec3(0.0) && b.finite()) {
            // Turning about the origin keeps every point within its distance of it.
            double r = 0.0;
            for (int c = 0; c < 8; ++c) {
                const Vec3 corner((c & 1) ? b.hi.x : b.lo.x, (c & 2) ? b.hi.y : b.lo.y,
                                  (c & 4) ? b.hi.z : b.lo.z);
                r = std::max(r, glm::length(corner));
            }
            r *= 1.0 + 0x1p-50;  // the rounding of the length and of the turned points
            swept = {Vec3(-r), Vec3(r)};
        } else if (mSpin != Vec3(0.0)) {
            swept = Bounds3::everything();
        }
        mBounds = Bounds3::hull(swept, {swept.lo + mVelocity, swept.hi + mVelocity});
    }

    void spans(const Ray& ray, double tmin, double tmax, TraceContext& ctx,
               SpanList& out) const override {
        const Rigid m = at(sceneTime());
        mChild->spans(m.toLocal(ray), tmin, tmax, ctx, out);
        for (Span& s : out) {
            s.in.normal = m.rotate * s.in.normal;
            s.out.normal = m.rotate * s.out.normal;
        }
    }

    bool firstSurface(const Ray& ray, double tmin, double tmax, TraceContext& ctx, Boundary& hit,
                      bool& entering) const override {
        const Rigid m = at(sceneTime());
        if (!mChild->firstSurface(m.toLocal(ray), tmin, tmax, ctx, hit, entering)) return false;
        hit.normal = m.rotate * hit.normal;
        return true;
    }

    bool anySurface(const Ray& ray, double tmin, double tmax, TraceContext& ctx) const override {
        return mChild->anySurface(at(sceneTime()).toLocal(ray), tmin, tmax, ctx);
    }

    double value(const Vec3& p) const override { return mChild->value(at(sceneTime()).toLocal(p)); }

    long double valueExtended(const LVec3& p) const override {
        const Rigid m = at(sceneTime());
        const glm::tmat3x3<long double> back = glm::transpose(glm::tmat3x3<long double>(m.rotate));
        return mChild->valueExtended(back * (p - LVec3(m.move)));
    }

    /// Over every time: the child's value over the box of all local points the world box maps
    /// to for some s in [0, 1].
    Interval valueInterval(const IntervalVec3& box) const override {
        const Interval sweep[3] = {
            Interval(std::min(0.0, mVelocity.x), std::max(0.0, mVelocity.x)),
            Interval(std::min(0.0, mVelocity.y), std::max(0.0, mVelocity.y)),
            Interval(std::min(0.0, mVelocity.z), std::max(0.0, mVelocity.z))};
        const Interval moved[3] = {box.x - sweep[0], box.y - sweep[1], box.z - sweep[2]};
        if (mSpin == Vec3(0.0)) return mChild->valueInterval({moved[0], moved[1], moved[2]});
        // Turned: every local point is within the moved box's farthest distance of the origin.
        double r2 = 0.0;
        for (const Interval& i : moved) {
            const double m = std::max(std::fabs(i.lo), std::fabs(i.hi));
            r2 += m * m;
        }
        const double r = std::sqrt(r2) * (1.0 + 0x1p-50);
        const Interval ball(-r, r);
        return mChild->valueInterval({ball, ball, ball});
    }

    NodeKind kind() const override { return NodeKind::Motion; }
    NodeParams params() const override { return MotionParams{mVelocity, mSpin}; }
    NodeSpan children() const override { return {&mChild, 1}; }
    NodePtr withChildren(std::vector<NodePtr> children) const override {
        return std::make_shared<MotionNode>(std::move(children.at(0)), mVelocity, mSpin);
    }

private:
    /// World from local at one time: p_world = rotate·p_local + move.
    struct Rigid {
        Mat3 rotate{1.0};
        Vec3 move{0.0};
        Vec3 toLocal(const Vec3& p) const { return glm::transpose(rotate) * (p - move); }
        Ray toLocal(const Ray& r) const {
            const Mat3 back = glm::transpose(rotate);
            return {back * (r.origin - move), back * r.dir};
        }
    };

    Rigid at(double s) const {
        Rigid m;
        if (mSpin != Vec3(0.0)) m.rotate = Affine::rotateDegrees(mSpin * s).linear;
        m.move = mVelocity * s;
        return m;
    }

    const NodePtr mChild;  // set once: trees are immutable
    Vec3 mVelocity;
    Vec3 mSpin;
};

}  // namespace

double sceneTime() { return tCurrentTime; }

SceneTimeScope::SceneTimeScope(double time) : mPrevious(tCurrentTime) { tCurrentTime = time; }
SceneTimeScope::~SceneTimeScope() { tCurrentTime = mPrevious; }

NodePtr makeMotion(NodePtr child, const Vec3& velocity, const Vec3& spin) {
    return std::make_shared<MotionNode>(std::move(child), velocity, spin);
}

}  // namespace kerf
