// The octree node: a ray walks the object's cell grid and searches for crossings only in the
// runs of boundary cells, each with the tree pruned to its cells.
#include "volume/octree/octree.h"

#include "csg/primitives/surfaces.h"

#include "csg/bvh/clip_ray.h"
#include "csg/tape/tape.h"
#include "csg/tree/kind_registry.h"
#include "volume/octree/cell_grid.h"
#include "volume/octree/octree_build.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <unordered_map>
#include <variant>

namespace kerf {

OctreeStats& OctreeStats::operator+=(const OctreeStats& o) {
    objects += o.objects;
    cellsClassified += o.cellsClassified;
    bricks += o.bricks;
    bricksBuilt += o.bricksBuilt;
    boundaryCells += o.boundaryCells;
    fullBlocks += o.fullBlocks;
    distinctNodes += o.distinctNodes;
    memoryBytes += o.memoryBytes;
    prunedTapeOps += o.prunedTapeOps;
    fullTapeOps += o.fullTapeOps;
    maxDepth = std::max(maxDepth, o.maxDepth);
    if (o.finestCell > 0.0 && (finestCell == 0.0 || o.finestCell < finestCell))
        finestCell = o.finestCell;
    return *this;
}

namespace {

/// Calls f on every distinct node of the tree once.
template <class F>
void forEachDistinct(const NodePtr& root, F&& f) {
    std::vector<const Node*> stack{root.get()};
    std::unordered_map<const Node*, bool> seen;
    while (!stack.empty()) {
        const Node* n = stack.back();
        stack.pop_back();
        if (!seen.emplace(n, true).second) continue;
        f(*n);
        for (const NodePtr& c : n->children()) stack.push_back(c.get());
    }
}

uint64_t implicitTapeOps(const NodePtr& node) {
    uint64_t ops = 0;
    forEachDistinct(node, [&](const Node& n) {
        if (n.kind() == NodeKind::Implicit)
            ops += uint64_t(std::get<ImplicitParams>(n.params()).tape->size());
    });
    return ops;
}

/// The grid for an object's bounds: a cube of 2^depth cells holding them.
GridFrame frameFor(const Bounds3& b, const OctreeOptions& options) {
    const Vec3 e = b.extent();
    const double longest = std::max({e.x, e.y, e.z});
    int depth = options.depth;
    if (depth <= 0) {
        // The finest cell spans kCellsPerFootprint pixels where the object is nearest, but
        // no nearer than a quarter of its size: a camera inside or against the bounds would
        // otherwise ask for the finest level over the whole object (its build and memory).
        const Vec3 nearest = glm::clamp(options.eye, b.lo, b.hi);
        const double distance =
            std::max(glm::length(nearest - options.eye), kNearestFraction * longest);
        const double cell = kCellsPerFootprint * options.footprintPerDistance * distance;
        depth = cell > 0.0 ? int(std::ceil(std::log2(longest / cell))) : kMaxOctreeDepth;
    }
    depth = std::clamp(depth, kMinOctreeDepth, kMaxOctreeDepth);
    GridFrame f;
    f.n = int32_t(1) << depth;
    // One cell of margin on every side: where the bounds' face is itself a surface (an
    // implicit's bound box), the cell beyond it is a boundary cell that rays must visit.
    // Rounded up so that origin + n·h reaches past the bounds on every axis.
    f.h = std::nextafter(longest / double(f.n - 2), kInf) * (1.0 + 1e-12);
    f.origin = b.lo - Vec3(f.h);
    return f;
}

class OctreeNode final : public Node {
public:
    OctreeNode(NodePtr object, const GridFrame& frame) : mObject(std::move(object)) {
        mBounds = mObject->bounds();
        mFullTapeOps = implicitTapeOps(mObject);
        CoarseCells coarse = classifyCoarse(mObject, frame);
        mCoarseClassified = coarse.classified;
        mFullBlocks = coarse.full.size();
        mGrid = std::make_unique<CellGrid>(
            frame, std::move(coarse.bricks), coarse.full,
            [this, frame](const CellCoord& corner, const NodePtr& node, BrickContent& out) {
                classifyBrick(frame, corner, node, out);
                std::vector<uint64_t> nodeOps;
                for (const NodePtr& n : out.nodes) nodeOps.push_back(implicitTapeOps(n));
                uint64_t ops = 0;
                for (uint16_t c : out.cell)
                    if (c) ops += nodeOps[c - 1u];
                mPrunedTapeOps.fetch_add(ops, std::memory_order_relaxed);
            });
        mCube = frame.cellBox({0, 0, 0}, frame.n);
        // Rounding slack of a segment end: a few ulps of the coordinates involved, in t.
        double magnitude = 0.0;
        for (int a = 0; a < 3; ++a)
            magnitude = std::max({magnitude, std::fabs(frame.origin[a]),
                                  std::fabs(frame.origin[a] + frame.n * frame.h)});
        mCoordinateSlack = 64.0 * 0x1p-52 * magnitude;
    }

    /// What this octree has built so far.
    OctreeStats stats() const {
        const CellGrid::Counts c = mGrid->counts();
        OctreeStats s;
        s.objects = 1;
        s.cellsClassified = mCoarseClassified + c.classified;
        s.bricks = c.bricks;
        s.bricksBuilt = c.bricksBuilt;
        s.boundaryCells = c.boundaryCells;
        s.fullBlocks = mFullBlocks;
        s.distinctNodes = c.distinctNodes;
        s.memoryBytes = c.memoryBytes + c.bricksBuilt * sizeof(BrickContent);
        s.prunedTapeOps = mPrunedTapeOps.load();
        s.fullTapeOps = mFullTapeOps * c.boundaryCells;
        s.maxDepth = int(std::log2(double(mGrid->frame().n)) + 0.5);
        s.finestCell = mGrid->frame().h;
        return s;
    }

    bool firstSurface(const Ray& ray, double tmin, double tmax, TraceContext& ctx, Boundary& hit,
                      bool& entering) const override {
        double t0 = tmin, t1 = tmax;
        if (!clipRayExact(mCube, ray, t0, t1)) return false;
        FirstSearch s{{&ray, &ctx, tmin, tmax, slackFor(ray)}, &hit, &entering};
        uint64_t steps = 0;
        const bool complete = mGrid->walk(ray, t0, t1, &FirstSearch::visit, &s, steps);
        ctx.stats.cellsVisited += steps;
        if (s.found) return true;
        if (s.flush()) return true;
        if (!complete) {  // the walk gave up (rounding): search the rest with the whole tree
            const double from = std::max(tmin, s.resumeFrom - s.slack);
            return mObject->firstSurface(ray, from, tmax, ctx, hit, entering);
        }
        return false;
    }

    void spans(const Ray& ray, double tmin, double tmax, TraceContext& ctx,
               SpanList& out) const override {
        out.clear();
        double t0 = tmin, t1 = tmax;
        if (!clipRayExact(mCube, ray, t0, t1)) return;
        ScratchSpans runSpans(ctx.scratch);
        SpanSearch s{{&ray, &ctx, t0, t1, slackFor(ray)},
                     &*runSpans,
                     &out,
                     [&](double t) { return mGrid->fullAt(ray.at(t)); },
                     false,
                     false,
                     {}};
        uint64_t steps = 0;
        const bool complete = mGrid->walk(ray, t0, t1, &SpanSearch::visit, &s, steps);
        ctx.stats.cellsVisited += steps;
        s.flush();
        if (!complete) return mObject->spans(ray, tmin, tmax, ctx, out);  // rounding: as is
        s.close();
        // No boundary cell on the way: the ray is all outside, or all inside full cells.
        if (!s.anyRun && mGrid->fullAt(ray.at(0.5 * t0 + 0.5 * t1))) {
            Boundary a, b;
            a.t = t0, b.t = t1;
            out.push_back({a, b});
        }
        dropThinSpans(out, ctx.relTolerance);
    }
    double value(const Vec3& p) const override { return mObject->value(p); }
    Interval valueInterval(const IntervalVec3& box) const override {
        return mObject->valueInterval(box);
    }
    long double valueExtended(const LVec3& p) const override { return mObject->valueExtended(p); }

    // To tree walkers it is the object itself.
    NodeKind kind() const override { return mObject->kind(); }
    NodeParams params() const override { return mObject->params(); }
    NodeSpan children() const override { return mObject->children(); }
    NodePtr withChildren(std::vector<NodePtr> children) const override {
        return mObject->withChildren(std::move(children));
    }

private:
    /// What both searches along the walk share: the ray and its range, and the run being
    /// gathered (consecutive segments of the same boundary cell tree, searched as one range).
    struct RunWalk {
        const Ray* ray;
        TraceContext* ctx;
        double tmin, tmax, slack;
        const Node* runNode = nullptr;
        double runStart = -kInf, runEnd = -kInf;

        /// The run's range widened by a margin of 4× the tolerance (plus the walk's rounding
        /// slack) past both ends, so that a span the run's ends cut is judged thin or not on
        /// its real extent, as the whole tree's search would judge it; within [tmin, tmax].
        void searchRange(double& lo, double& hi) const {
            const double margin =
                4.0 * ctx->relTolerance * std::max(std::fabs(runStart), std::fabs(runEnd)) + slack;
            lo = std::max(tmin, runStart - margin);
            hi = std::min(tmax, runEnd + margin);
        }
    };

    /// The state of one first-surface search along the walk.
    struct FirstSearch : RunWalk {
        Boundary* hit;
        bool* entering;
        bool found = false;

        double resumeFrom = -kInf;  ///< where a search of the rest would have to start

        /// Searches the pending run; true if it holds the first surface. The search reaches
        /// a margin past both ends so that a span cut by the run's end is judged thin or not
        /// (dropThinSpans) on its real extent, as the whole tree's search would judge it;
        /// crossings found in the margins belong to the neighbouring runs and are passed over.
        bool flush() {
            if (!runNode) return false;
            const Node& tree = *runNode;
            runNode = nullptr;
            resumeFrom = runEnd;
            const double first = runStart - slack, last = runEnd + slack;
            double lo, hi;
            searchRange(lo, hi);
            // The first crossing over the run and its margins (thin spans judged on their
            // whole extent, as the whole tree's search judges them); one in the margin after
            // the run is the next run's.
            if (!tree.firstSurface(*ray, lo, hi, *ctx, *hit, *entering)) return false;
            if (hit->t > last) return false;
            if (hit->t > first) return found = true;
            // Rarely, the first crossing lies in the margin before the run, the previous
            // run's, which did not take it. Then the run's spans decide: the first surface
            // boundary inside the run. (Restarting the search past that crossing would judge
            // the span it opens on its far end alone, and can find it again at its own start.)
            ScratchSpans spans(ctx->scratch);
            tree.spans(*ray, lo, hi, *ctx, *spans);
            for (const Span& sp : *spans) {
                if (!(sp.in.t < sp.out.t)) continue;  // a zero-width touch is not a crossing
                for (const bool in : {true, false}) {
                    const Boundary& b = in ? sp.in : sp.out;
                    if (!b.isSurface() || !(b.t > first) || !(b.t > tmin)) continue;
                    if (b.t > last || b.t > tmax) return false;  // the next run's
                    *hit = b;
                    *entering = in;
                    return found = true;
                }
            }
            return false;
        }

        static bool visit(void* context, const GridSegment& seg) {
            auto& s = *static_cast<FirstSearch*>(context);
            if (seg.node && seg.node == s.runNode) {
                s.runEnd = seg.t1;
                return true;
            }
            if (s.flush()) return false;
            if (!seg.node) {
                s.resumeFrom = seg.t1;
                return true;
            }
            s.runNode = seg.node;
            s.runStart = seg.t0;
            s.runEnd = seg.t1;
            return true;
        }
    };

    /// The state of one spans() walk: each run's spans, from its tree over the run and
    /// margins past both ends (so that thinness is judged on real extents), cut at the run's
    /// ends and joined to the previous run's where the ray stays inside across the cut.
    struct SpanSearch : RunWalk {
        SpanList* runSpans;
        SpanList* out;
        /// Whether the point of the ray at t lies in a full cell.
        std::function<bool(double)> fullBefore;
        bool anyRun = false;
        /// The last output span ends at a cut (the ray was inside at the run's end); `realEnd`
        /// is where that run's tree ended it (a surface in the margin, or a clip).
        bool openAtCut = false;
        Boundary realEnd;

        static Boundary cutAt(const Boundary& real, double t) {
            Boundary b = real;  // keeps the material and normal, but is no surface
            b.t = t;
            b.primitive = 0;
            return b;
        }

        void flush() {
            if (!runNode) return;
            const Node& tree = *runNode;
            runNode = nullptr;
            double lo, hi;
            searchRange(lo, hi);
            tree.spans(*ray, lo, hi, *ctx, *runSpans);
            const bool firstRun = !anyRun;
            anyRun = true;
            const bool wasOpen = openAtCut;  // the previous run ended inside, at its cut
            bool first = true;
            for (const Span& sp : *runSpans) {
                // Inside from the search's start through full cells, leaving in the margin
                // before the first run (a face on the line between a full cell and this
                // boundary cell): no earlier run holds that span, so this one gives it.
                // (The tree is the run's cells' own: before its search range it may differ from
                // the object, so the span must end in that range, after full cells.)
                if (firstRun && first && sp.in.t <= lo && sp.out.t > tmin && sp.out.t >= lo &&
                    !(sp.out.t > runStart) && fullBefore && fullBefore(0.5 * (tmin + lo))) {
                    Span piece = sp;
                    if (!sp.in.isSurface()) piece.in = cutAt(sp.in, tmin);
                    out->push_back(piece);
                    first = false;
                    realEnd = sp.out;
                    continue;
                }
                if (!(sp.out.t > runStart) || !(sp.in.t < runEnd)) continue;  // the neighbours'
                Span piece = sp;
                const bool startsBefore = sp.in.t <= runStart;
                // An end exactly at the run's end is this run's (ranges are closed above).
                const bool endsAfter = sp.out.t > runEnd;
                if (endsAfter) piece.out = cutAt(sp.out, runEnd);
                if (first && wasOpen && startsBefore) {  // inside across the cut: one span
                    out->back().out = piece.out;
                } else {
                    if (first && wasOpen) closeOpen();
                    // Inside from the start through full cells (a clip at the search's start),
                    // or entered in the margin (its real entry).
                    if (startsBefore && firstRun && !sp.in.isSurface())
                        piece.in = cutAt(sp.in, tmin);
                    out->push_back(piece);
                }
                first = false;
                openAtCut = endsAfter;
                realEnd = sp.out;
            }
            if (first && wasOpen) closeOpen();
        }

        /// A span left open at a cut that the next run does not continue ends where its own
        /// tree ended it.
        void closeOpen() {
            out->back().out = realEnd;
            openAtCut = false;
        }

        /// After the walk: a span open at the last cut ends where its tree ended it, or runs
        /// on through full cells to the end of the range.
        void close() {
            if (!openAtCut) return;
            out->back().out =
                realEnd.isSurface() && realEnd.t <= tmax ? realEnd : cutAt(realEnd, tmax);
            openAtCut = false;
        }

        static bool visit(void* context, const GridSegment& seg) {
            auto& s = *static_cast<SpanSearch*>(context);
            if (seg.node && seg.node == s.runNode) {
                s.runEnd = seg.t1;
                return true;
            }
            s.flush();
            if (seg.node) {
                s.runNode = seg.node;
                s.runStart = seg.t0;
                s.runEnd = seg.t1;
            }
            return true;
        }
    };

    /// Slack in t for segment ends: coordinate rounding over the ray's speed, plus t's own.
    double slackFor(const Ray& ray) const {
        const double speed =
            std::max({std::fabs(ray.dir.x), std::fabs(ray.dir.y), std::fabs(ray.dir.z)});
        double o =
            std::max({std::fabs(ray.origin.x), std::fabs(ray.origin.y), std::fabs(ray.origin.z)});
        return (mCoordinateSlack + 64.0 * 0x1p-52 * o) / speed;
    }

    NodePtr mObject;
    std::unique_ptr<CellGrid> mGrid;
    uint64_t mCoarseClassified = 0, mFullBlocks = 0, mFullTapeOps = 0;
    std::atomic<uint64_t> mPrunedTapeOps{0};
    Bounds3 mCube;  ///< the grid's cube: the bounds and a margin of one cell
    double mCoordinateSlack = 0.0;
};

}  // namespace

bool hasImplicitLeaf(const NodePtr& node) {
    bool found = false;
    forEachDistinct(node, [&](const Node& n) { found = found || kindTraits(n.kind()).octreeLeaf; });
    return found;
}

bool hasExternalField(const NodePtr& node) {
    bool found = false;
    forEachDistinct(node, [&](const Node& n) {
        if (found) return;
        if (kindTraits(n.kind()).ownWalk) found = true;
        if (n.kind() != NodeKind::Implicit) return;  // the fields an implicit's tape calls
        for (const TapeInstr& in : std::get<ImplicitParams>(n.params()).tape->instrs())
            if (in.op == Op::Field) found = true;
    });
    return found;
}

namespace {

/// The longest side of any implicit leaf's bounds, in the object's space: each leaf's own
/// bound scaled by the largest column norm of the transforms above it (an upper bound on how
/// much they stretch it; rotations keep it). Each (node, scale) is visited once.
double largestImplicitExtent(const NodePtr& object) {
    double largest = 0.0;
    std::vector<std::pair<const Node*, double>> stack{{object.get(), 1.0}};
    std::unordered_map<const Node*, double> seen;  // the largest scale a node was seen at
    while (!stack.empty()) {
        const auto [n, scale] = stack.back();
        stack.pop_back();
        auto [it, added] = seen.emplace(n, scale);
        if (!added) {
            if (scale <= it->second) continue;
            it->second = scale;
        }
        double childScale = scale;
        if (n->kind() == NodeKind::Transform) {
            const Mat3 m = std::get<TransformParams>(n->params()).worldFromLocal.linear;
            childScale *= std::max({glm::length(m[0]), glm::length(m[1]), glm::length(m[2])});
        }
        if (kindTraits(n->kind()).octreeLeaf) {
            const Vec3 e = n->bounds().extent();
            largest = std::max(largest, scale * std::max({e.x, e.y, e.z}));
        }
        for (const NodePtr& c : n->children()) stack.push_back({c.get(), childScale});
    }
    return largest;
}

}  // namespace

bool octreePays(const NodePtr& object, const OctreeOptions& options) {
    const Bounds3& b = object->bounds();
    if (b.empty() || !b.finite() || !hasImplicitLeaf(object)) return false;
    if (isSurfaceTree(*object))
        return false;  // csg/primitives/surfaces.h: no inside to classify cells by
    if (hasExternalField(object)) return false;
    return largestImplicitExtent(object) >= kMinImplicitCells * frameFor(b, options).h;
}

NodePtr withOctree(const NodePtr& object, const OctreeOptions& options) {
    const Bounds3& b = object->bounds();
    if (b.empty() || !b.finite()) return object;
    return std::make_shared<OctreeNode>(object, frameFor(b, options));
}

OctreeStats octreeStats(const std::vector<NodePtr>& objects) {
    OctreeStats total;
    for (const NodePtr& o : objects)
        if (const auto* tree = dynamic_cast<const OctreeNode*>(o.get())) total += tree->stats();
    return total;
}

}  // namespace kerf
