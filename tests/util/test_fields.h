// External scalar fields with closed forms, for the tests of Op::Field (csg/tape/scalar_field.h):
// the exact signed distance to a sphere (smooth but at its centre) and to an axis-aligned box
// (kinks on the medial planes, as a mesh's distance has). Their ranges are the same formulas
// in interval arithmetic: sound, and exact up to rounding where each term depends on one axis.
#pragma once

#include <algorithm>
#include <cmath>

#include "csg/interval/interval.h"
#include "csg/tape/scalar_field.h"

namespace kerf::test {

/// |p − centre| − radius.
class SphereField final : public ScalarField {
public:
    SphereField(const Vec3& centre, double radius) : mCentre(centre), mRadius(radius) {}

    double value(const Vec3& p) const override { return glm::length(p - mCentre) - mRadius; }
    long double valueExtended(const glm::tvec3<long double>& p) const override {
        const glm::tvec3<long double> d = p - glm::tvec3<long double>(mCentre);
        return std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z) - (long double)mRadius;
    }
    double valueGradient(const Vec3& p, Vec3& gradient) const override {
        const double r = glm::length(p - mCentre);
        gradient = r > 0.0 ? (p - mCentre) / r : Vec3(0.0);
        return r - mRadius;  // value()'s bits
    }
    Interval range(const Interval& x, const Interval& y, const Interval& z) const override {
        const Interval s = sqr(x - mCentre.x) + sqr(y - mCentre.y) + sqr(z - mCentre.z);
        return sqrt(nonNegative(s)) - Interval(mRadius);  // a sum of squares: no NaN flag
    }

    /// The exact range over a box in long double: nearest and farthest points of the box.
    void exactRange(const Bounds3& box, long double& lo, long double& hi) const {
        long double near2 = 0.0L, far2 = 0.0L;
        for (int a = 0; a < 3; ++a) {
            const long double l = (long double)box.lo[a] - mCentre[a];
            const long double h = (long double)box.hi[a] - mCentre[a];
            const long double n = l > 0.0L ? l : h < 0.0L ? h : 0.0L;
            const long double f = std::max(std::fabs(l), std::fabs(h));
            near2 += n * n;
            far2 += f * f;
        }
        lo = std::sqrt(near2) - mRadius;
        hi = std::sqrt(far2) - mRadius;
    }

private:
    Vec3 mCentre;
    double mRadius;
};

/// The signed distance to the box centre ± half: outside, the length of the excess over each
/// face; inside, minus the distance to the nearest face.
class BoxField final : public ScalarField {
public:
    BoxField(const Vec3& centre, const Vec3& half) : mCentre(centre), mHalf(half) {}

    double value(const Vec3& p) const override {
        Vec3 g;
        return valueGradient(p, g);
    }
    long double valueExtended(const glm::tvec3<long double>& p) const override {
        long double q[3], outside = 0.0L;
        for (int a = 0; a < 3; ++a) {
            q[a] = std::fabs(p[a] - (long double)mCentre[a]) - (long double)mHalf[a];
            if (q[a] > 0.0L) outside += q[a] * q[a];
        }
        const long double inside = std::min(std::max({q[0], q[1], q[2]}), 0.0L);
        return std::sqrt(outside) + inside;
    }
    double valueGradient(const Vec3& p, Vec3& gradient) const override {
        Vec3 q, sign;
        for (int a = 0; a < 3; ++a) {
            const double d = p[a] - mCentre[a];
            q[a] = std::fabs(d) - mHalf[a];
            sign[a] = d < 0.0 ? -1.0 : 1.0;
        }
        const Vec3 excess = glm::max(q, Vec3(0.0));
        const double outside = glm::length(excess);
        if (outside > 0.0) {
            gradient = excess * sign / outside;
            return outside;
        }
        const int a = q.x >= q.y && q.x >= q.z ? 0 : q.y >= q.z ? 1 : 2;  // the nearest face
        gradient = Vec3(0.0);
        gradient[a] = sign[a];
        return std::min(q[a], 0.0);
    }
    Interval range(const Interval& x, const Interval& y, const Interval& z) const override {
        const Interval* axes[3] = {&x, &y, &z};
        Interval q[3], outside(0.0);
        for (int a = 0; a < 3; ++a) {
            q[a] = abs(*axes[a] - mCentre[a]) - Interval(mHalf[a]);
            outside = outside + sqr(max(q[a], Interval(0.0)));
        }
        return sqrt(nonNegative(outside)) + min(max(max(q[0], q[1]), q[2]), Interval(0.0));
    }

private:
    Vec3 mCentre, mHalf;
};

}  // namespace kerf::test
