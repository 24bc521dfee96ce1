/// @file slice/contourer.h
/// @brief The contourer behind contourSection (slice/contour.h), internal to slice/: the
/// quadtree of interval-classified cells (slice/contour.cpp) and the boundary it traces through
/// them (slice/contour_boundary.cpp).
#pragma once

#include "slice/contour.h"
#include "slice/section_tape.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

namespace kerf::contour_detail {

using Pt = std::array<double, 2>;

/// A lattice point of the finest level, in units of the finest cell.
struct Key {
    int64_t x, y;
    bool operator==(const Key& o) const { return x == o.x && y == o.y; }
};
struct KeyHash {
    size_t operator()(const Key& k) const {
        uint64_t h = static_cast<uint64_t>(k.x) * 0x9E3779B97F4A7C15ull;
        h ^= static_cast<uint64_t>(k.y) + 0x7F4A7C159E3779B9ull + (h << 6) + (h >> 2);
        return static_cast<size_t>(h);
    }
};
/// An edge piece between two neighbouring lattice points, first the smaller.
struct EdgeKey {
    Key a, b;
    bool operator==(const EdgeKey& o) const { return a == o.a && b == o.b; }
};
struct EdgeKeyHash {
    size_t operator()(const EdgeKey& k) const { return KeyHash()(k.a) * 31 + KeyHash()(k.b); }
};

enum class State : uint8_t { Empty, Full, Boundary };
/// How a boundary leaf's curve is followed: lines of constant v (f monotone in u), of
/// constant u, either (monotone in both), or not at all (a finest cell).
enum class Simple : uint8_t { None, AlongU, AlongV, Both };

struct Cell {
    int64_t x, y;
    int level;
    int firstChild = -1;  // four consecutive cells: (x, y), (x+h, y), (x, y+h), (x+h, y+h)
    State state = State::Boundary;
    Simple simple = Simple::None;
    std::shared_ptr<const Tape> tape;  // boundary leaves only
    int8_t slopeU = 0, slopeV = 0;     // sign of ∂f/∂u, ∂f/∂v where proved (simple cells)
};

struct Chain {
    int from, to;           // crossing vertices
    std::vector<Pt> inner;  // vertices between them
};

class Contourer {
public:
    Contourer(const Tape& tape, double w, const ContourOptions& o, ContourStats& stats)
        : mW(w), mTol(o.tolerance), mStats(stats) {
        // The root square holds the rectangle with a margin of odd (non-dyadic) size, so the
        // lattice lines seldom fall exactly on a model's round coordinates: a face lying on a
        // cell edge makes f ≡ 0 there, which interval rounding cannot call inside, and the
        // cells along it would all be split to the finest level.
        const double extent = std::max(o.rect.maxU - o.rect.minU, o.rect.maxV - o.rect.minV);
        const double side = extent * 1.0731;
        mU0 = o.rect.minU - extent * 0.0317;
        mV0 = o.rect.minV - extent * 0.0291;
        // Finest cells of at most half the tolerance: a straight segment across one is within
        // the tolerance of whatever curve crosses it.
        const double ratio = side / (0.5 * mTol);
        mDepth = ratio > 1.0 ? std::min(44, static_cast<int>(std::ceil(std::log2(ratio)))) : 1;
        mUnit = side / std::ldexp(1.0, mDepth);
        mFlat = std::ldexp(side, -44);
        stats.depth = mDepth;
        mCells.push_back(Cell{0, 0, 0, -1, State::Boundary, Simple::None, nullptr});
        build(std::shared_ptr<const Tape>(std::shared_ptr<const Tape>(), &tape));
    }

    std::vector<SectionLoop> run();

private:
    int64_t sizeOf(int level) const { return int64_t(1) << (mDepth - level); }
    double uOf(int64_t x) const { return mU0 + static_cast<double>(x) * mUnit; }
    double vOf(int64_t y) const { return mV0 + static_cast<double>(y) * mUnit; }
    double evalAt(const Tape& t, double u, double v) {
        ++mStats.pointEvals;
        return t.eval(Vec3(u, v, mW));
    }

    /// Classifies cell `index` with its parent's tape; a boundary cell keeps its own
    /// (simplified) tape in `tape`. True when the cell is to be split.
    bool classify(int index, const std::shared_ptr<const Tape>& parentTape,
                  std::shared_ptr<const Tape>& tape);
    void build(const std::shared_ptr<const Tape>& rootTape);
    Simple provedSimple(const Tape& tape, const Interval& U, const Interval& V, Cell& cell);
    void edgeSplits(int node, int side, const Cell& c, std::vector<int64_t>& out) const;
    bool inside(const Key& k, const Tape& t);
    int crossing(const Key& a, const Key& b, bool aInside, const Tape& t);
    /// A point within the tolerance of a root of f on the segment from `in` (f = fin ≤ 0) to
    /// `out` (f = fout > 0), starting from the fraction `guess` (or the secant's, if outside
    /// (0, 1)).
    Pt rootOnSegment(const Tape& t, const Pt& in, const Pt& out, double fin, double fout,
                     double guess = -1.0, double accuracy = 0.25);
    void contourCell(const Cell& c);
    /// In a finest cell, the vertex where two operands' boundaries meet between crossings a
    /// and b, if they do.
    void placeCorner(const Cell& c, const Pt& a, const Pt& b, std::vector<Pt>& out);
    void refine(const Cell& c, const Pt& p, const Pt& q, int depth, std::vector<Pt>& out);

    static constexpr size_t kMaxCells = size_t(1) << 21;
    double mW, mTol, mU0 = 0, mV0 = 0, mUnit = 1;
    double mFlat = 0.0;  ///< the rounding scale of f within which a cell is taken as flat
    int mDepth = 1;
    ContourStats& mStats;
    std::vector<Cell> mCells;
    std::vector<Choice> mChoices;
    std::vector<Interval> mScratch;
    std::unordered_map<Key, bool, KeyHash> mSign;
    std::unordered_map<EdgeKey, int, EdgeKeyHash> mCrossing;
    std::vector<Pt> mVertices;
    std::vector<Chain> mChains;
};

}  // namespace kerf::contour_detail
