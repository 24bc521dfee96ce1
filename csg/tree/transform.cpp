// Transform and material nodes: the two modifiers that wrap a shared subtree.
#include "csg/tree/solids.h"

namespace kerf {

namespace {

/// The child seen through an affine map. The ray goes into the child's space by the inverse
/// map with its direction not renormalised, so t is the same in both spaces; normals come
/// back by the inverse transpose.
class TransformNode final : public Node {
public:
    TransformNode(NodePtr child, const Affine& worldFromLocal)
        : mChild(std::move(child)),
          mWorldFromLocal(worldFromLocal),
          mLocalFromWorld(worldFromLocal.inverse()),
          mNormalToWorld(glm::transpose(mLocalFromWorld.linear)),
          mWorldFromLocalExtended(glm::tmat3x3<long double>(worldFromLocal.linear)),
          mLocalFromWorldExtended(glm::inverse(mWorldFromLocalExtended)),
          mOffsetExtended(worldFromLocal.offset) {
        mBounds = worldFromLocal.map(mChild->bounds());
    }

    /// The same maps (the inverses copied, not recomputed) over another child.
    TransformNode(NodePtr child, const TransformNode& same) : TransformNode(same) {
        mChild = std::move(child);
        mBounds = mWorldFromLocal.map(mChild->bounds());
    }

    void spans(const Ray& ray, double tmin, double tmax, TraceContext& ctx,
               SpanList& out) const override {
        const Ray local{mLocalFromWorld.point(ray.origin), mLocalFromWorld.vector(ray.dir)};
        mChild->spans(local, tmin, tmax, ctx, out);
        for (Span& s : out) {
            s.in.normal = mNormalToWorld * s.in.normal;
            s.out.normal = mNormalToWorld * s.out.normal;
        }
    }

    bool firstSurface(const Ray& ray, double tmin, double tmax, TraceContext& ctx, Boundary& hit,
                      bool& entering) const override {
        const Ray local{mLocalFromWorld.point(ray.origin), mLocalFromWorld.vector(ray.dir)};
        if (!mChild->firstSurface(local, tmin, tmax, ctx, hit, entering)) return false;
        hit.normal = mNormalToWorld * hit.normal;
        return true;
    }

    bool anySurface(const Ray& ray, double tmin, double tmax, TraceContext& ctx) const override {
        const Ray local{mLocalFromWorld.point(ray.origin), mLocalFromWorld.vector(ray.dir)};
        return mChild->anySurface(local, tmin, tmax, ctx);
    }

    double value(const Vec3& p) const override { return mChild->value(mLocalFromWorld.point(p)); }

    long double valueExtended(const LVec3& p) const override {
        return mChild->valueExtended(mLocalFromWorldExtended * (p - mOffsetExtended));
    }

    Interval valueInterval(const IntervalVec3& box) const override {
        const Interval in[3] = {box.x, box.y, box.z};
        Interval out[3];
        for (int row = 0; row < 3; ++row) {
            Interval acc(mLocalFromWorld.offset[row]);
            for (int col = 0; col < 3; ++col) {
                const double m = mLocalFromWorld.linear[col][row];
                if (m != 0.0) acc = acc + Interval(m) * in[col];
            }
            out[row] = acc;
        }
        return mChild->valueInterval({out[0], out[1], out[2]});
    }

    NodeKind kind() const override { return NodeKind::Transform; }
    NodeParams params() const override { return TransformParams{mWorldFromLocal, mLocalFromWorld}; }
    NodeSpan children() const override { return {&mChild, 1}; }
    NodePtr withChildren(std::vector<NodePtr> children) const override {
        return std::make_shared<TransformNode>(std::move(children.at(0)), *this);
    }

private:
    NodePtr mChild;
    Affine mWorldFromLocal;  ///< as given, for params()
    Affine mLocalFromWorld;
    Mat3 mNormalToWorld;
    // The map inverted in long double, so references do not inherit the double inverse's error.
    glm::tmat3x3<long double> mWorldFromLocalExtended;
    glm::tmat3x3<long double> mLocalFromWorldExtended;
    LVec3 mOffsetExtended;
};

/// Gives the child's boundaries that have no material yet this one: the innermost wins.
class MaterialNode final : public Node {
public:
    MaterialNode(NodePtr child, int32_t material) : mChild(std::move(child)), mMaterial(material) {
        mBounds = mChild->bounds();
    }

    void spans(const Ray& ray, double tmin, double tmax, TraceContext& ctx,
               SpanList& out) const override {
        mChild->spans(ray, tmin, tmax, ctx, out);
        fillMaterial(out, mMaterial);
    }

    bool firstSurface(const Ray& ray, double tmin, double tmax, TraceContext& ctx, Boundary& hit,
                      bool& entering) const override {
        if (!mChild->firstSurface(ray, tmin, tmax, ctx, hit, entering)) return false;
        if (!hit.hasMaterial()) hit.material = mMaterial;
        return true;
    }

    bool anySurface(const Ray& ray, double tmin, double tmax, TraceContext& ctx) const override {
        return mChild->anySurface(ray, tmin, tmax, ctx);
    }

    double value(const Vec3& p) const override { return mChild->value(p); }
    long double valueExtended(const LVec3& p) const override { return mChild->valueExtended(p); }
    Interval valueInterval(const IntervalVec3& box) const override {
        return mChild->valueInterval(box);
    }

    NodeKind kind() const override { return NodeKind::Material; }
    NodeParams params() const override { return MaterialParams{mMaterial}; }
    NodeSpan children() const override { return {&mChild, 1}; }
    NodePtr withChildren(std::vector<NodePtr> children) const override {
        return std::make_shared<MaterialNode>(std::move(children.at(0)), mMaterial);
    }

private:
    const NodePtr mChild;  // set once: trees are immutable
    int32_t mMaterial;
};

}  // namespace

NodePtr makeTransform(NodePtr child, const Affine& worldFromLocal) {
    return std::make_shared<TransformNode>(std::move(child), worldFromLocal);
}

NodePtr makeMaterial(NodePtr child, int32_t material) {
    return std::make_shared<MaterialNode>(std::move(child), material);
}

}  // namespace kerf
