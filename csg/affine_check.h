/// @file csg/affine_check.h
/// @brief Whether an affine map can serve as a transform: finite, with a finite inverse, and
/// not singular, each judged without overflow and relative to the map's own scale, so a map
/// scaled by 1e300 or 1e-300 is as good as the same map at scale 1.
#pragma once

#include "csg/types.h"

namespace kerf {

enum class AffineStatus {
    Ok,
    NotFinite,         ///< an entry of the map is inf or NaN
    Singular,          ///< it flattens space: a zero row or column, or a relative determinant ~0
    InverseNotFinite,  ///< finite and regular, but its inverse overflows (scale below ~1e-308)
};

/// Below this relative determinant a map counts as singular: its columns, each scaled to
/// unit size, span less than this volume (a dimensionless measure, never a scene scale).
constexpr double kSingularRelativeDeterminant = 1e-12;

/// |det| of the linear part over the product of its column lengths, in [0, 1] (Hadamard),
/// computed after scaling rows and then columns by powers of two (exact), so it neither
/// overflows nor underflows. 0 when a row or column is zero; NaN when an entry is not finite.
double relativeDeterminant(const Mat3& m);

/// The first problem of `a` in the order of AffineStatus, or Ok.
AffineStatus checkAffine(const Affine& a);

/// Rows and columns of m scaled by powers of two (exact) so each one's largest entry is in
/// [1, 2): m = 2^rowExp · n · 2^colExp (diagonal scalings) for the n returned. Rows first or
/// columns first, whichever leaves n better conditioned. Affine::inverse inverts n.
Mat3 equilibrate(const Mat3& m, int rowExp[3], int colExp[3]);

}  // namespace kerf
