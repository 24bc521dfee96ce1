// Checks of affine maps, and the power-of-two equilibration they and Affine::inverse share.
#include "csg/affine_check.h"

#include <glm/gtc/matrix_access.hpp>

#include <algorithm>
#include <cmath>

namespace kerf {

namespace {

bool finite(const Mat3& m) {
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

}  // namespace

namespace {

void scaleRows(Mat3& n, int rowExp[3]) {
    for (int r = 0; r < 3; ++r) {
        const double big = std::max({std::fabs(n[0][r]), std::fabs(n[1][r]), std::fabs(n[2][r])});
        rowExp[r] = big > 0 && std::isfinite(big) ? std::ilogb(big) : 0;
        for (int c = 0; c < 3; ++c) n[c][r] = std::ldexp(n[c][r], -rowExp[r]);
    }
}

void scaleColumns(Mat3& n, int colExp[3]) {
    for (int c = 0; c < 3; ++c) {
        const double big = std::max({std::fabs(n[c][0]), std::fabs(n[c][1]), std::fabs(n[c][2])});
        colExp[c] = big > 0 && std::isfinite(big) ? std::ilogb(big) : 0;
        for (int r = 0; r < 3; ++r) n[c][r] = std::ldexp(n[c][r], -colExp[c]);
    }
}

/// |det n| over the product of n's column lengths (n has entries of order 1); 0 for a zero
/// row or column.
double hadamardRatio(const Mat3& n) {
    const double lengths = glm::length(n[0]) * glm::length(n[1]) * glm::length(n[2]);
    const double rowLengths =
        glm::length(glm::row(n, 0)) * glm::length(glm::row(n, 1)) * glm::length(glm::row(n, 2));
    if (!(lengths > 0) || !(rowLengths > 0)) return 0.0;
    return std::fabs(glm::determinant(n)) / lengths;
}

}  // namespace

Mat3 equilibrate(const Mat3& m, int rowExp[3], int colExp[3]) {
    // Rows first suits S·R (a scale applied after a rotation), columns first R·S; the other
    // order can flush a whole column or row to zero. Both are exact where nothing underflows,
    // so the better of the two is taken.
    Mat3 a = m, b = m;
    int ra[3], ca[3], rb[3], cb[3];
    scaleRows(a, ra);
    scaleColumns(a, ca);
    scaleColumns(b, cb);
    scaleRows(b, rb);
    const bool rowsFirst = !(hadamardRatio(b) > hadamardRatio(a));
    for (int i = 0; i < 3; ++i) {
        rowExp[i] = rowsFirst ? ra[i] : rb[i];
        colExp[i] = rowsFirst ? ca[i] : cb[i];
    }
    return rowsFirst ? a : b;
}

double relativeDeterminant(const Mat3& m) {
    if (!finite(m)) return std::nan("");
    int rowExp[3], colExp[3];
    return hadamardRatio(equilibrate(m, rowExp, colExp));
}

AffineStatus checkAffine(const Affine& a) {
    if (!finite(a.linear) || !std::isfinite(a.offset.x) || !std::isfinite(a.offset.y) ||
        !std::isfinite(a.offset.z))
        return AffineStatus::NotFinite;
    if (!(relativeDeterminant(a.linear) > kSingularRelativeDeterminant))
        return AffineStatus::Singular;
    const Affine inv = a.inverse();
    if (!finite(inv.linear) || !std::isfinite(inv.offset.x) || !std::isfinite(inv.offset.y) ||
        !std::isfinite(inv.offset.z))
        return AffineStatus::InverseNotFinite;
    return AffineStatus::Ok;
}

}  // namespace kerf
