// The capsule in the language (lang/solid_kinds.cpp): its properties and defaults reach the
// node, its errors name the property at fault with line and column, and its keyword is
// reserved.
#include "csg/tree/node_kind.h"
#include "lang_test_util.h"

using namespace kerf;
using namespace kerf::test;

TEST_CASE("lang: capsule { from to radius }") {
    SECTION("the properties reach the node") {
        const NodePtr n = firstObject("object capsule { from <1, 2, 3> to <4, 5, 6> radius 0.5 };");
        REQUIRE(n->kind() == NodeKind::Capsule);
        const auto p = std::get<CapsuleParams>(n->params());
        CHECK(p.a == Vec3(1, 2, 3));
        CHECK(p.b == Vec3(4, 5, 6));
        CHECK(p.radius == 0.5);
    }
    SECTION("radius defaults to 1, and a capsule is a solid value") {
        const NodePtr n =
            firstObject("let c = capsule { from <0, 0, 0> to <0, 1, 0> };\nobject c;");
        REQUIRE(n->kind() == NodeKind::Capsule);
        CHECK(std::get<CapsuleParams>(n->params()).radius == 1.0);
    }
    SECTION("a capsule is an operand of a Boolean") {
        const NodePtr n = firstObject(
            "object difference { box { min <-1, -1, -1> max <1, 1, 1> }\n"
            "  capsule { from <0, 0, -2> to <0, 0, 2> radius 0.25 } };");
        CHECK(n->kind() == NodeKind::Difference);
        CHECK(n->value(Vec3(0, 0, 0)) > 0.0);      // in the capsule: cut away
        CHECK(n->value(Vec3(0.5, 0.5, 0)) < 0.0);  // in the box, outside the capsule
    }
}

TEST_CASE("lang: capsule errors") {
    requireOneError("object capsule { from <0,0,0> to <0,1,0> radius -1 };", 1, 49,
                    "capsule radius must be positive, got -1");
    requireOneError("object a;\nsolid a = capsule { from <0,0,0> to <0,1,0>\n  radius 0 };", 3, 10,
                    "capsule radius must be positive, got 0");
    requireOneError("object capsule { from <1,2,3> to <1,2,3> };", 1, 8,
                    "capsule has zero length: from and to are the same point");
    requireOneError("object capsule { from <0,0,0> radius 1 };", 1, 8, "to");
    requireOneError("object capsule { from <0,0,0> to <0,1,0> radius 1 height 2 };", 1, 51,
                    "height");
    requireOneError("let capsule = 1;\nobject sphere { };", 1, 5, "'capsule' is a reserved word");
    requireOneError("object capsule;", 1, 8, "'capsule' needs a block");
}
