// The section's boundary through the quadtree's leaves: crossings on cell edges, chains refined
// to the tolerance, corners placed, and the chains joined into loops.
#include "slice/contourer.h"

namespace kerf::contour_detail {

bool Contourer::inside(const Key& k, const Tape& t) {
    auto it = mSign.find(k);
    if (it != mSign.end()) return it->second;
    // Any leaf's simplified tape gives the same doubles at a point of its closed cell.
    const bool in = evalAt(t, uOf(k.x), vOf(k.y)) <= 0.0;
    mSign.emplace(k, in);
    return in;
}

Pt Contourer::rootOnSegment(const Tape& t, const Pt& in, const Pt& out, double fin, double fout,
                            double guess, double accuracy) {
    // The secant method on s ∈ [0, 1] along in → out from the guess and a point a tolerance
    // away, kept inside the bracket [lo, hi] (f(lo) ≤ 0 < f(hi)): a step that would leave it
    // is replaced by Illinois regula falsi on the bracket. Ends when a step is below a quarter
    // of accuracy × tolerance (superlinear convergence puts the root far closer) or the
    // bracket is within accuracy × tolerance.
    const double du = out[0] - in[0], dv = out[1] - in[1];
    const double len = std::hypot(du, dv);
    auto at = [&](double s) { return Pt{in[0] + s * du, in[1] + s * dv}; };
    // fin, fout may be NaN: not evaluated, the ends' signs known from a proof.
    if ((!std::isnan(fin) && !(fin <= 0.0)) || (!std::isnan(fout) && !(fout > 0.0)) || !(len > 0.0))
        return at(0.5);
    double lo = 0.0, hi = 1.0, flo = fin, fhi = fout;
    const double step = mTol / len;
    double s = guess > 0.0 && guess < 1.0 ? guess : fin / (fin - fout);
    if (!(s > 0.0 && s < 1.0)) s = 0.5;
    double sPrev = -1.0, fPrev = 0.0;
    int stale = 0;  // Illinois: halve the end that stays put twice in a row
    for (int iter = 0; iter < 100; ++iter) {
        if ((hi - lo) * len <= accuracy * mTol) break;
        const Pt p = at(s);
        const double f = evalAt(t, p[0], p[1]);
        if (f == 0.0) return p;
        if (f < 0.0) {
            lo = s;
            flo = f;
            stale = stale <= 0 ? stale - 1 : -1;
        } else if (f > 0.0) {
            hi = s;
            fhi = f;
            stale = stale >= 0 ? stale + 1 : 1;
        } else {
            break;  // NaN: keep the bracket
        }
        double next;
        if (sPrev < 0.0)
            next = f < 0.0 ? s + step : s - step;  // the second point
        else
            next = f != fPrev ? s - f * (s - sPrev) / (f - fPrev) : -1.0;
        if (!(next > lo && next < hi)) {
            double a = flo, b = fhi;
            if (stale <= -2) b *= 0.5;
            if (stale >= 2) a *= 0.5;
            next = lo + (hi - lo) * (a / (a - b));  // NaN (an end not evaluated): bisect
            if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        } else if (sPrev >= 0.0 && std::fabs(next - s) * len <= 0.25 * accuracy * mTol) {
            return at(next);
        }
        sPrev = s;
        fPrev = f;
        s = next;
    }
    const double k = (flo < 0.0 && fhi > 0.0) ? flo / (flo - fhi) : 0.5;
    return at(lo + (hi - lo) * k);
}

int Contourer::crossing(const Key& a, const Key& b, bool aInside, const Tape& t) {
    const bool aFirst = a.x < b.x || (a.x == b.x && a.y < b.y);
    const EdgeKey key = aFirst ? EdgeKey{a, b} : EdgeKey{b, a};
    auto it = mCrossing.find(key);
    if (it != mCrossing.end()) return it->second;
    const Key& in = aInside ? a : b;
    const Key& out = aInside ? b : a;
    const Pt pin{uOf(in.x), vOf(in.y)}, pout{uOf(out.x), vOf(out.y)};
    // Crossings to a 64th of the tolerance: corners are placed from them (placeCorner).
    const Pt p = rootOnSegment(t, pin, pout, evalAt(t, pin[0], pin[1]), evalAt(t, pout[0], pout[1]),
                               -1.0, 1.0 / 64.0);
    const int id = static_cast<int>(mVertices.size());
    mVertices.push_back(p);
    mCrossing.emplace(key, id);
    return id;
}

void Contourer::refine(const Cell& c, const Pt& p, const Pt& q, int depth, std::vector<Pt>& out) {
    if (depth > 60) return;
    const Tape& t = *c.tape;
    // Lines of constant v (a root along u) or of constant u.
    bool lineOfV;
    if (c.simple == Simple::AlongU)
        lineOfV = true;
    else if (c.simple == Simple::AlongV)
        lineOfV = false;
    else
        lineOfV = std::fabs(q[1] - p[1]) > std::fabs(q[0] - p[0]);
    const int param = lineOfV ? 1 : 0;
    if (std::fabs(q[param] - p[param]) <= mTol) return;
    const double m = 0.5 * (p[param] + q[param]);
    const int64_t h = sizeOf(c.level);
    Pt a, b;  // the line across the cell
    if (lineOfV) {
        a = {uOf(c.x), m};
        b = {uOf(c.x + h), m};
    } else {
        a = {m, vOf(c.y)};
        b = {m, vOf(c.y + h)};
    }
    // Start from where the chord meets the line: within the chord's error of the curve.
    const double k = (m - p[param]) / (q[param] - p[param]);
    const double other = p[1 - param] + k * (q[1 - param] - p[1 - param]);
    const double g = (other - a[1 - param]) / (b[1 - param] - a[1 - param]);
    // The line meets the curve once, and the proved slope along it says which end is inside:
    // its ends need no evaluation.
    const int slope = lineOfV ? c.slopeU : c.slopeV;
    const double unknown = std::nan("");
    Pt mid;
    if (slope > 0) {
        mid = rootOnSegment(t, a, b, unknown, unknown, g);
    } else if (slope < 0) {
        mid = rootOnSegment(t, b, a, unknown, unknown, 1.0 - g);
    } else {
        const double fa = evalAt(t, a[0], a[1]), fb = evalAt(t, b[0], b[1]);
        if (fa <= 0.0 && fb > 0.0)
            mid = rootOnSegment(t, a, b, fa, fb, g);
        else if (fb <= 0.0 && fa > 0.0)
            mid = rootOnSegment(t, b, a, fb, fa, 1.0 - g);
        else
            return;  // no sign change (rounding at the very end of the curve): keep the chord
    }
    // Distance of the curve's point from the chord p–q.
    const double dx = q[0] - p[0], dy = q[1] - p[1];
    const double len = std::hypot(dx, dy);
    const double dev = len > 0.0 ? std::fabs(dx * (mid[1] - p[1]) - dy * (mid[0] - p[0])) / len
                                 : std::hypot(mid[0] - p[0], mid[1] - p[1]);
    // Within a quarter of the tolerance the chord stands. Up to twice the tolerance the point
    // found is kept and the two halves are not checked: an arc's halves deviate a quarter as
    // much (a corner's at most half), so they are within the tolerance; the root found to
    // check a chord is not wasted.
    if (dev <= 0.25 * mTol) return;
    if (dev <= 2.0 * mTol) {
        out.push_back(mid);
        return;
    }
    refine(c, p, mid, depth + 1, out);
    out.push_back(mid);
    refine(c, mid, q, depth + 1, out);
}

void Contourer::placeCorner(const Cell& c, const Pt& a, const Pt& b, std::vector<Pt>& out) {
    // As dual contouring does: where the boundary's normals at the two crossings differ by
    // more than 20°, two operands' boundaries meet in the cell (a CSG edge); the corner is
    // where their tangent lines at the crossings meet, kept if it lies in the cell. The cell
    // is at most half the tolerance wide, so any point of it is within the tolerance of the
    // boundary; the corner is then exact up to the curvature of the operands across the cell.
    Vec3 ga, gb;
    mStats.pointEvals += 2;
    c.tape->evalGradient(Vec3(a[0], a[1], mW), ga);
    c.tape->evalGradient(Vec3(b[0], b[1], mW), gb);
    const double la = std::hypot(ga.x, ga.y), lb = std::hypot(gb.x, gb.y);
    if (!(la > 0.0) || !(lb > 0.0) || !std::isfinite(la) || !std::isfinite(lb)) return;
    const double ax = ga.x / la, ay = ga.y / la, bx = gb.x / lb, by = gb.y / lb;
    if (ax * bx + ay * by > 0.94) return;  // cos 20°: a smooth turn, the segment stands
    const double det = ax * by - ay * bx;
    if (std::fabs(det) < 1e-6) return;  // parallel tangents: no corner between them
    const double ra = ax * a[0] + ay * a[1], rb = bx * b[0] + by * b[1];
    const Pt corner{(ra * by - ay * rb) / det, (ax * rb - ra * bx) / det};
    const int64_t h = sizeOf(c.level);
    if (corner[0] < uOf(c.x) || corner[0] > uOf(c.x + h) || corner[1] < vOf(c.y) ||
        corner[1] > vOf(c.y + h))
        return;
    out.push_back(corner);
}

void Contourer::contourCell(const Cell& c) {
    const Tape& t = *c.tape;
    const int64_t h = sizeOf(c.level);
    // The cell's boundary, counter-clockwise, through every corner of smaller neighbours.
    std::vector<Key> ring;
    std::vector<int64_t> splits;
    const Key corner[4] = {{c.x, c.y}, {c.x + h, c.y}, {c.x + h, c.y + h}, {c.x, c.y + h}};
    for (int side = 0; side < 4; ++side) {
        ring.push_back(corner[side]);
        splits.clear();
        if (h > 1) edgeSplits(0, side, c, splits);
        std::sort(splits.begin(), splits.end());
        splits.erase(std::unique(splits.begin(), splits.end()), splits.end());
        if (side >= 2) std::reverse(splits.begin(), splits.end());
        for (const int64_t s : splits)
            ring.push_back(side == 0   ? Key{s, c.y}
                           : side == 1 ? Key{c.x + h, s}
                           : side == 2 ? Key{s, c.y + h}
                                       : Key{c.x, s});
    }
    const size_t n = ring.size();
    std::vector<char> in(n);
    for (size_t i = 0; i < n; ++i) in[i] = inside(ring[i], t);
    // Crossings in ring order; they alternate between leaving (in → out) and entering.
    struct X {
        int vertex;
        bool leaving;
    };
    std::vector<X> xs;
    for (size_t i = 0; i < n; ++i) {
        const size_t j = (i + 1) % n;
        if (in[i] != in[j]) xs.push_back({crossing(ring[i], ring[j], in[i], t), bool(in[i])});
    }
    if (xs.empty()) return;
    const size_t m = xs.size();
    // A segment runs from a leaving crossing to an entering one, inside on its left. With
    // more than two, the centre's sign says whether the inside joins across the cell (pair
    // with the next entering crossing) or not (the previous one).
    bool joinNext = true;
    if (m > 2) joinNext = evalAt(t, uOf(c.x) + 0.5 * h * mUnit, vOf(c.y) + 0.5 * h * mUnit) <= 0.0;
    for (size_t i = 0; i < m; ++i) {
        if (!xs[i].leaving) continue;
        const X& to = xs[joinNext ? (i + 1) % m : (i + m - 1) % m];
        Chain chain{xs[i].vertex, to.vertex, {}};
        if (c.simple != Simple::None && m == 2)
            refine(c, mVertices[chain.from], mVertices[chain.to], 0, chain.inner);
        else if (m == 2)
            placeCorner(c, mVertices[chain.from], mVertices[chain.to], chain.inner);
        mChains.push_back(std::move(chain));
    }
}

std::vector<SectionLoop> Contourer::run() {
    for (const Cell& c : mCells) {
        if (c.firstChild >= 0 || c.state != State::Boundary) continue;
        ++mStats.boundaryLeaves;
        if (c.simple != Simple::None) ++mStats.simpleLeaves;
        contourCell(c);
    }
    // Link the chains: each crossing ends one chain and starts the next.
    std::vector<int> startsAt(mVertices.size(), -1);
    for (size_t i = 0; i < mChains.size(); ++i) startsAt[mChains[i].from] = static_cast<int>(i);
    std::vector<char> used(mChains.size(), 0);
    std::vector<SectionLoop> loops;
    for (size_t first = 0; first < mChains.size(); ++first) {
        if (used[first]) continue;
        SectionLoop loop;
        int at = static_cast<int>(first);
        bool closed = false;
        while (at >= 0 && !used[at]) {
            used[at] = 1;
            const Chain& ch = mChains[at];
            loop.points.push_back(mVertices[ch.from]);
            loop.points.insert(loop.points.end(), ch.inner.begin(), ch.inner.end());
            at = startsAt[ch.to];
            if (at == static_cast<int>(first)) closed = true;
        }
        if (!closed) ++mStats.repairedLoops;  // closed by its last segment back to the start
        if (loop.points.size() >= 3) loops.push_back(std::move(loop));
    }
    return loops;
}

}  // namespace kerf::contour_detail
