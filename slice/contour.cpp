// The section's quadtree: cells classified by interval evaluation of the section tape, coarse
// to fine, boundary leaves proved simple where they are; contourSection (below) runs it and
// traces the boundary (slice/contour_boundary.cpp).
#include "slice/contour.h"

#include "slice/contourer.h"

namespace kerf {
namespace contour_detail {

Simple Contourer::provedSimple(const Tape& tape, const Interval& U, const Interval& V, Cell& cell) {
    const IntervalSlopes s = evalIntervalSlopes(tape, U, V, mW, mScratch);
    if (!s.ok) return Simple::None;
    const bool monoU = s.du.lo > 0.0 || s.du.hi < 0.0;
    const bool monoV = s.dv.lo > 0.0 || s.dv.hi < 0.0;
    cell.slopeU = monoU ? (s.du.lo > 0.0 ? 1 : -1) : 0;
    cell.slopeV = monoV ? (s.dv.lo > 0.0 ? 1 : -1) : 0;
    if (monoU && monoV) return Simple::Both;
    // Monotone in one direction: the edge where f is least must be wholly inside and the
    // opposite one wholly outside; then every line along that direction crosses once.
    // An edge's values, narrowed by the mean-value form about its middle with the cell's slope
    // along it: a distance field's direct enclosure (middle ± half the edge) never proves an
    // edge parallel to an outline one-signed.
    auto edgeRange = [&](bool alongU, double end) {
        const Interval& along = alongU ? V : U;
        const double mid = along.mid();
        const Interval direct =
            alongU ? tape.evalInterval(end, V, mW) : tape.evalInterval(U, end, mW);
        const Interval middle =
            alongU ? tape.evalInterval(end, mid, mW) : tape.evalInterval(mid, end, mW);
        const Interval centred = middle + (alongU ? s.dv : s.du) * (along - Interval(mid));
        const Interval both(std::max(direct.lo, centred.lo), std::min(direct.hi, centred.hi));
        return direct.maybeNan || centred.maybeNan || !(both.lo <= both.hi) ? direct : both;
    };
    auto edgesSplit = [&](bool alongU, bool increasing) {
        const Interval& across = alongU ? U : V;
        const double lowEnd = increasing ? across.lo : across.hi;
        const double highEnd = increasing ? across.hi : across.lo;
        return edgeRange(alongU, lowEnd).classify() == Classification::Filled &&
               edgeRange(alongU, highEnd).classify() == Classification::Empty;
    };
    if (monoU && edgesSplit(true, s.du.lo > 0.0)) return Simple::AlongU;
    if (monoV && edgesSplit(false, s.dv.lo > 0.0)) return Simple::AlongV;
    return Simple::None;
}

bool Contourer::classify(int index, const std::shared_ptr<const Tape>& parentTape,
                         std::shared_ptr<const Tape>& tape) {
    ++mStats.cells;
    const Cell c = mCells[index];
    const int64_t h = sizeOf(c.level);
    const Interval U(uOf(c.x), uOf(c.x + h)), V(vOf(c.y), vOf(c.y + h));
    const Interval f = parentTape->evalInterval(U, V, Interval(mW), mChoices);
    const Classification k = f.classify();
    if (k != Classification::Ambiguous) {
        mCells[index].state = k == Classification::Empty ? State::Empty : State::Full;
        return false;
    }
    // Only a decided min/max makes a shorter tape worth building.
    bool decided = false;
    for (const Choice ch : mChoices) decided = decided || ch != Choice::Both;
    tape = decided ? parentTape->simplified(mChoices) : parentTape;
    mCells[index].tape = tape;
    // f within rounding of 0 on one side over the whole cell: a face lying in the plane.
    // Intervals cannot prove the sign of an exact 0, so splitting would go to the finest
    // level over the whole face; the cell is contoured as it is, by its samples (f ≤ 0
    // inside). Only a feature whose f stays within this rounding scale could be missed.
    if ((f.hi <= mFlat || f.lo >= -mFlat) && !f.maybeNan) {
        ++mStats.flatCells;
        return false;
    }
    mCells[index].simple = provedSimple(*tape, U, V, mCells[index]);
    return mCells[index].simple == Simple::None && c.level < mDepth;
}

void Contourer::build(const std::shared_ptr<const Tape>& rootTape) {
    // Level by level, so that if the cell budget runs out (faces that coincide inside a
    // union, where intervals cannot prove f ≤ 0, split to the finest level along the whole
    // face), every part of the plane has been refined to the same level and the cells left
    // are contoured at that size: coarser than the tolerance, but closed and consistent.
    struct Pending {
        int index;
        std::shared_ptr<const Tape> tape;
    };
    std::vector<Pending> level{{0, rootTape}}, split, next;
    while (!level.empty()) {
        split.clear();
        for (const Pending& p : level) {
            std::shared_ptr<const Tape> tape;
            if (classify(p.index, p.tape, tape)) split.push_back({p.index, std::move(tape)});
        }
        if (mCells.size() + 4 * split.size() > kMaxCells) {
            if (!split.empty()) mStats.budgetExceeded = true;
            break;  // the cells of `split` stay boundary leaves, contoured by their samples
        }
        next.clear();
        for (Pending& p : split) {
            const Cell c = mCells[p.index];
            const int64_t half = sizeOf(c.level) / 2;
            const int first = static_cast<int>(mCells.size());
            mCells[p.index].firstChild = first;
            mCells[p.index].tape.reset();
            for (int i = 0; i < 4; ++i) {
                mCells.push_back(Cell{c.x + (i & 1) * half, c.y + (i >> 1) * half, c.level + 1, -1,
                                      State::Boundary, Simple::None, nullptr});
                next.push_back({first + i, p.tape});
            }
        }
        level.swap(next);
    }
}

/// Lattice coordinates strictly inside one side of leaf c where leaves across that side
/// begin or end (side 0 bottom, 1 right, 2 top, 3 left), in no particular order.
void Contourer::edgeSplits(int node, int side, const Cell& c, std::vector<int64_t>& out) const {
    const Cell& n = mCells[node];
    const int64_t h = sizeOf(n.level), ch = sizeOf(c.level);
    // The row or column just across the side, and the span along it.
    const bool horizontal = side == 0 || side == 2;
    const int64_t across = side == 0   ? c.y - 1
                           : side == 1 ? c.x + ch
                           : side == 2 ? c.y + ch
                                       : c.x - 1;
    const int64_t lo = horizontal ? c.x : c.y;
    const int64_t nAcross = horizontal ? n.y : n.x;
    const int64_t nAlong = horizontal ? n.x : n.y;
    if (across < nAcross || across >= nAcross + h) return;
    if (nAlong + h <= lo || nAlong >= lo + ch) return;
    if (n.firstChild < 0) {
        if (nAlong > lo) out.push_back(nAlong);
        if (nAlong + h < lo + ch) out.push_back(nAlong + h);
        return;
    }
    for (int i = 0; i < 4; ++i) edgeSplits(n.firstChild + i, side, c, out);
}

}  // namespace contour_detail

using contour_detail::Contourer;

std::vector<SectionLoop> contourSection(const Tape& tape, double w, const ContourOptions& options,
                                        ContourStats& stats) {
    if (options.rect.empty()) return {};
    Contourer c(tape, w, options, stats);
    return c.run();
}

}  // namespace kerf
