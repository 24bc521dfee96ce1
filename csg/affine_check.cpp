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

Mat3 equilibrate(const Mat3& m, int rowExp[3], int colExp[3]) {
    Mat3 n = m;
    for (int r = 0; r < 3; ++r) {
        const double big = std::max({std::fabs(n[0][r]), std::fabs(n[1][r]), std::fabs(n[2][r])});
        rowExp[r] = big > 0 && std::isfinite(big) ? std::ilogb(big) : 0;
        for (int c = 0; c < 3; ++c) n[c][r] = std::ldexp(n[c][r], -rowExp[r]);
    }
    for (int c = 0; c < 3; ++c) {
        const double big = std::max({std::fabs(n[c][0]), std::fabs(n[c][1]), std::fabs(n[c][2])});
        colExp[c] = big > 0 && std::isfinite(big) ? std::ilogb(big) : 0;
        for (int r = 0; r < 3; ++r) n[c][r] = std::ldexp(n[c][r], -colExp[c]);
    }
    return n;
}

double relativeDeterminant(const Mat3& m) {
    if (!finite(m)) return std::nan("");
    int rowExp[3], colExp[3];
    const Mat3 n = equilibrate(m, rowExp, colExp);
    // Every nonzero row and column now has its largest entry in [1, 2): nothing below
    // overflows, and a zero length means a zero column (or row).
    const double lengths = glm::length(n[0]) * glm::length(n[1]) * glm::length(n[2]);
    if (!(lengths > 0)) return 0.0;
    const double rowLengths = glm::length(glm::row(n, 0)) * glm::length(glm::row(n, 1)) *
                              glm::length(glm::row(n, 2));
    if (!(rowLengths > 0)) return 0.0;
    return std::fabs(glm::determinant(n)) / lengths;
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
