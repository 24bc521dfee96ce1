// Affine maps and primitives at the ends of the double range: the inverse of a map scaled by
// 1e±300 (glm's determinant overflowed at 1e103), the relative determinant's independence of
// scale, checkAffine's verdicts, and rays with an infinite origin or direction.
#include "csg/affine_check.h"
#include "csg/tree/solids.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace kerf;

TEST_CASE("Affine::inverse at scales 1e-300 to 1e300") {
    for (const double s : {1e-300, 1e-200, 1e-105, 1.0, 1e105, 1e200, 1e300}) {
        INFO("scale " << s);
        const Affine a = Affine::rotateDegrees(Vec3(10, 20, 30)).after(Affine::scale(Vec3(s)));
        const Affine inv = Affine::translate(Vec3(0.0)).after(a.inverse());
        // inverse ∘ a is the identity: map a unit vector there and back.
        for (const Vec3& v : {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0.3, -0.5, 0.8)}) {
            const Vec3 back = inv.vector(a.vector(v));
            CHECK(glm::length(back - v) <= 1e-14);
        }
        CHECK(checkAffine(a) == AffineStatus::Ok);
    }
    // Anisotropic: each axis inverted on its own, to a few ulps (glm rounds the cofactor and
    // 1/det apart).
    const Affine d = Affine::scale(Vec3(1e-300, 1.0, 1e300)).inverse();
    CHECK(d.linear[0][0] == Approx(1e300).epsilon(1e-15));
    CHECK(d.linear[1][1] == Approx(1.0).epsilon(1e-15));
    CHECK(d.linear[2][2] == Approx(1e-300).epsilon(1e-15));
}

TEST_CASE("relativeDeterminant: the same at every scale, 0 when singular") {
    const Mat3 m =
        Affine::rotateDegrees(Vec3(10, 20, 30)).linear * Mat3(1, 0, 0, 0.5, 1, 0, 0, 0, 2);
    const double unit = relativeDeterminant(m);
    CHECK(unit > 0.1);
    for (const double s : {1e-300, 1e-150, 1e150, 1e300})
        CHECK(relativeDeterminant(s * m) == Approx(unit).epsilon(1e-14));
    CHECK(relativeDeterminant(Mat3(1, 2, 3, 2, 4, 6, 0, 0, 1)) <= kSingularRelativeDeterminant);
    CHECK(relativeDeterminant(Mat3(0.0)) == 0.0);
    CHECK(std::isnan(relativeDeterminant(Mat3(kInf))));
}

TEST_CASE("checkAffine: not finite, singular, inverse not finite") {
    Affine inf = Affine::translate(Vec3(1e308, 0, 0));
    inf.offset.x *= 2.0;
    CHECK(checkAffine(inf) == AffineStatus::NotFinite);
    CHECK(checkAffine(Affine::scale(Vec3(1e-200)).after(Affine::scale(Vec3(1e-200)))) ==
          AffineStatus::Singular);
    CHECK(checkAffine(Affine::scale(Vec3(1e-310))) == AffineStatus::InverseNotFinite);
    CHECK(checkAffine(Affine::scale(Vec3(1e-300))) == AffineStatus::Ok);
    CHECK(checkAffine(Affine::scale(Vec3(1e300))) == AffineStatus::Ok);
}

TEST_CASE("closed-form primitives: an infinite ray origin or direction meets nothing") {
    const NodePtr solids[] = {makeSphere(Vec3(0.0), 1.0),
                              makeCylinder(Vec3(0, -1, 0), Vec3(0, 1, 0), 1.0),
                              makeCone(Vec3(0, -1, 0), Vec3(0, 1, 0), 1.0, 0.2)};
    const Ray rays[] = {{Vec3(kInf, 0, 0), Vec3(-1, 0, 0)},
                        {Vec3(-kInf, 0.1, 0), Vec3(1, 0, 0)},
                        {Vec3(-5, 0.1, 0), Vec3(kInf, 0, 0)},
                        {Vec3(-5, 0.1, 0), Vec3(1e-320, 0, 0)}};
    for (const NodePtr& solid : solids)
        for (const Ray& ray : rays) {
            TraceContext ctx;
            SpanList out;
            solid->spans(ray, -kInf, kInf, ctx, out);
            for (const Span& s : out) {
                CHECK_FALSE(std::isnan(s.in.t));
                CHECK_FALSE(std::isnan(s.out.t));
            }
        }
}
