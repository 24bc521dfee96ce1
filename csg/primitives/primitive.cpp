// Primitive ids: handed out once per primitive, in creation order; the evaluations derived
// from a primitive's implicit form.
#include "csg/primitives/primitive.h"

#include "csg/tape/tape.h"

#include <atomic>

namespace kerf {

uint32_t nextPrimitiveId() {
    static std::atomic<uint32_t> counter{0};
    return ++counter;
}

const Tape& Primitive::derivedTape() const {
    if (const auto tape = std::atomic_load(&mDerivedTape)) return *tape;
    ExprGraph g;
    const ExprId x = g.x(), y = g.y(), z = g.z();
    const ExprId root = implicitExpr(g, x, y, z);
    std::shared_ptr<const Tape> fresh = Tape::compile(g, root);
    std::shared_ptr<const Tape> expected;  // null: keep the first tape stored
    std::atomic_compare_exchange_strong(&mDerivedTape, &expected, fresh);
    return *std::atomic_load(&mDerivedTape);
}

double Primitive::derivedValue(const Vec3& p) const { return derivedTape().eval(p); }

long double Primitive::derivedValueExtended(const LVec3& p) const {
    return derivedTape().evalExtended(p);
}

Interval Primitive::derivedValueInterval(const IntervalVec3& box) const {
    return derivedTape().evalInterval(box.x, box.y, box.z);
}

}  // namespace kerf
