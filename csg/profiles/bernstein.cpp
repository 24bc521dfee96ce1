// Class changes of a polynomial in Bernstein form (csg/profiles/bernstein.h).
#include "csg/profiles/bernstein.h"

#include <cmath>

namespace kerf {

namespace {

struct BernsteinPiece {
    BernsteinCoefficients c;  ///< the polynomial on [lo, hi], reparametrised to [0, 1]
    double lo, hi;
    int depth;
};

int countClassChanges(const BernsteinCoefficients& c, int degree) {
    int n = 0;
    for (int i = 0; i < degree; ++i) n += (c[i] > 0.0) != (c[i + 1] > 0.0);
    return n;
}

/// The halves of a piece (de Casteljau at ½).
void splitInHalves(const BernsteinPiece& p, int degree, BernsteinPiece& left,
                   BernsteinPiece& right) {
    BernsteinCoefficients b = p.c;
    const double mid = 0.5 * (p.lo + p.hi);
    left = {{}, p.lo, mid, p.depth + 1};
    right = {{}, mid, p.hi, p.depth + 1};
    for (int r = 0; r <= degree; ++r) {
        left.c[r] = b[0];
        right.c[degree - r] = b[degree - r];
        for (int i = 0; i + r < degree; ++i) b[i] = 0.5 * (b[i] + b[i + 1]);
    }
}

/// The one class change of p on [0, 1] of its own parameter (its ends of two classes): the
/// bracket kept by class, narrowed by regula falsi with the Illinois halving, then mapped to
/// [lo, hi].
double changeInPiece(const BernsteinPiece& p, int degree) {
    double a = 0.0, b = 1.0, fa = p.c[0], fb = p.c[degree];
    const bool classA = fa > 0.0;
    int kept = 0;  // which end stayed last time (−1 a, 1 b)
    for (int it = 0; it < 100 && b - a > 0x1p-52; ++it) {
        double s = (a * fb - b * fa) / (fb - fa);
        if (!(s > a && s < b)) s = 0.5 * (a + b);
        const double fs = bernsteinValue(p.c, degree, s);
        if ((fs > 0.0) == classA) {
            a = s;
            fa = fs;
            if (kept == -1) fb *= 0.5;
            kept = -1;
        } else {
            b = s;
            fb = fs;
            if (kept == 1) fa *= 0.5;
            kept = 1;
        }
        if (fs == 0.0) break;
    }
    // A change at an end of the curve (a root on the end, the rest of one class) gives that
    // end exactly, as the neighbour finds it. (A zero at an end is no shortcut: the class may
    // change inside, where the curve dips through zero before reaching the end.)
    if (a == 0.0 && p.c[0] == 0.0) return p.lo;
    return b == 1.0 ? p.hi : p.lo + b * (p.hi - p.lo);
}

}  // namespace

void bernsteinClassChanges(const BernsteinCoefficients& c, int degree, std::vector<double>& out) {
    BernsteinPiece stack[2 * 64];
    int n = 0;
    stack[n++] = {c, 0.0, 1.0, 0};
    while (n > 0) {
        const BernsteinPiece p = stack[--n];
        const int changes = countClassChanges(p.c, degree);
        if (changes == 0) continue;
        const bool ends = (p.c[0] > 0.0) != (p.c[degree] > 0.0);
        // One change among the coefficients: one root. Deep enough: the ends decide (the
        // piece is below rounding, and the count stays even around a loop either way).
        if (changes == 1 || p.depth >= 40) {
            if (ends) out.push_back(changeInPiece(p, degree));
            continue;
        }
        BernsteinPiece left, right;
        splitInHalves(p, degree, left, right);
        stack[n++] = right;
        stack[n++] = left;
    }
}

}  // namespace kerf
