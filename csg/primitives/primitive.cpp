// Primitive ids: handed out once per primitive, in creation order.
#include "csg/primitives/primitive.h"

#include <atomic>

namespace kerf {

uint32_t nextPrimitiveId() {
    static std::atomic<uint32_t> counter{0};
    return ++counter;
}

}  // namespace kerf
