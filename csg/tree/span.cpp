// The Boolean algebra of spans (Roth 1982): merge the boundary events of two span lists in t
// order, track inside/outside of each operand, and emit a boundary wherever the result changes.
#include "csg/tree/span.h"

#include <algorithm>
#include <cmath>

#include "csg/check.h"

namespace kerf {

namespace {

// Below this relative width a span or gap is rounding noise even for closed forms: coincident
// faces computed by different formulas differ by a few ulps of t.
constexpr double kRoundingFloor = 32.0 * 0x1p-52;

bool evaluate(BoolOp op, bool a, bool b) {
    switch (op) {
        case BoolOp::Union: return a || b;
        case BoolOp::Intersection: return a && b;
        case BoolOp::Difference: return a && !b;
        case BoolOp::Xor: return a != b;
    }
    return false;
}

const Boundary& boundaryAt(const SpanList& s, int k) {
    return (k & 1) ? s[k >> 1].out : s[k >> 1].in;
}

/// Every span list's contract: sorted and disjoint, i.e. its boundaries in t order (NaN fails).
bool sortedDisjoint(const SpanList& s) {
    for (int k = 1; k < 2 * s.size(); ++k)
        if (!(boundaryAt(s, k - 1).t <= boundaryAt(s, k).t)) return false;
    return true;
}

/// Whether the stretch between two boundaries is no wider than their own error: rounding for
/// closed-form surfaces, the tolerance they were isolated to for root-found ones (capped by
/// the caller's tolerance). A thin sheet of closed-form faces therefore survives any
/// tolerance, while a sliver between root-found surfaces that cannot be told apart vanishes.
bool thin(const Boundary& a, const Boundary& b, double relTolerance) {
    if (!std::isfinite(a.t) || !std::isfinite(b.t)) return false;
    const double found = std::max<double>(a.relError, b.relError);
    const double rel = std::max(kRoundingFloor, std::min(relTolerance, found));
    return b.t - a.t <= rel * std::max(std::fabs(a.t), std::fabs(b.t));
}

/// Which of two boundaries at the same t comes first when the tie is broken (< 0: a, > 0: b,
/// 0: undecided). A clip stands for a surface somewhere beyond the range it clips, so it
/// comes before the surfaces at t when the ray enters there and after them when it leaves;
/// surfaces go in primitive order. The order depends on neither operand's position, so the
/// children of a commutative operation give the same boundaries in any order.
int tieOrder(const Boundary& a, bool aEnters, const Boundary& b, bool bEnters) {
    auto rank = [](const Boundary& x, bool enters) { return x.isSurface() ? 0 : enters ? -1 : 1; };
    const int ra = rank(a, aEnters), rb = rank(b, bEnters);
    if (ra != rb) return ra < rb ? -1 : 1;
    if (a.primitive != b.primitive) return a.primitive < b.primitive ? -1 : 1;
    return 0;
}

}  // namespace

void SpanList::grow() {
    const int capacity = mCapacity * 2;
    Span* data = static_cast<Span*>(::operator new(sizeof(Span) * capacity));
    std::memcpy(static_cast<void*>(data), mData, sizeof(Span) * mSize);
    if (mData != inlineData()) ::operator delete(static_cast<void*>(mData));
    mData = data;
    mCapacity = capacity;
}

void combineSpans(BoolOp op, const SpanList& a, const SpanList& b, double relTolerance,
                  SpanList& out) {
    KERF_DCHECK(sortedDisjoint(a) && sortedDisjoint(b) && &out != &a && &out != &b);
    out.clear();
    const int na = 2 * a.size(), nb = 2 * b.size();
    int ia = 0, ib = 0;
    bool inA = false, inB = false, inResult = false;
    while (ia < na || ib < nb) {
        const double ta = ia < na ? boundaryAt(a, ia).t : kInf;
        const double tb = ib < nb ? boundaryAt(b, ib).t : kInf;
        // At equal t both events happen at once: coincident faces are decided as if they
        // coincided exactly, so a shared face leaves no sliver and abutting solids no seam.
        const bool takeA = ia < na && (ib >= nb || ta <= tb);
        const bool takeB = ib < nb && (ia >= na || tb <= ta);
        const bool wasA = inA, wasB = inB;
        if (takeA) inA = !inA;
        if (takeB) inB = !inB;
        const bool now = evaluate(op, inA, inB);
        if (now != inResult) {
            // The boundary that made the change: A's when A alone would have made it, else B's.
            // Two events at once are taken in tie order, the first making the change if it
            // alone would have; only boundaries tieOrder cannot tell apart (two clips, or one
            // primitive reached twice) keep the fixed preference for A.
            bool fromA = takeA && evaluate(op, inA, wasB) != evaluate(op, wasA, wasB);
            if (takeA && takeB) {
                const int order = tieOrder(boundaryAt(a, ia), inA, boundaryAt(b, ib), inB);
                if (order < 0) fromA = evaluate(op, inA, wasB) != inResult;
                if (order > 0) fromA = evaluate(op, wasA, inB) == inResult;
            }
            Boundary bd = fromA ? boundaryAt(a, ia) : boundaryAt(b, ib);
            // The result's outward normal: a cutter's surface faces the other way, and so does
            // either operand's surface where it lies inside the other operand of a xor.
            const bool flip =
                (op == BoolOp::Difference && !fromA) || (op == BoolOp::Xor && (fromA ? inB : inA));
            if (flip) bd.normal = -bd.normal;
            if (now) {
                out.push_back(Span{bd, bd});
            } else {
                out.back().out = bd;
            }
            inResult = now;
        }
        if (takeA) ++ia;
        if (takeB) ++ib;
    }
    dropThinSpans(out, relTolerance);
    KERF_DCHECK(sortedDisjoint(out));
}

void dropThinSpans(SpanList& s, double relTolerance) {
    int w = 0;
    for (int r = 0; r < s.size(); ++r) {
        // A gap thinner than its boundaries' error closes: the spans on both sides join.
        if (w > 0 && thin(s[w - 1].out, s[r].in, relTolerance)) {
            s[w - 1].out = s[r].out;
            continue;
        }
        s[w++] = s[r];
    }
    int k = 0;
    for (int r = 0; r < w; ++r)
        if (!thin(s[r].in, s[r].out, relTolerance) && s[r].out.t > s[r].in.t) s[k++] = s[r];
    s.truncate(k);
}

void fillMaterial(SpanList& s, int32_t material) {
    for (Span& span : s) {
        if (!span.in.hasMaterial()) span.in.material = material;
        if (!span.out.hasMaterial()) span.out.material = material;
    }
}

}  // namespace kerf
