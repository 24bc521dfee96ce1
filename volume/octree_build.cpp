// Coarse-to-fine classification of an object's octree cells by interval pruning.
#include "volume/octree_build.h"

#include "csg/prune.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>

namespace kerf {

namespace {

struct Pending {
    CellCoord corner;
    int32_t size;
    NodePtr node;  ///< the parent's pruned tree: equal to the object inside this cell
};

/// Classifies one cell and, if the surface may cross it, its children (depth first).
void classify(const GridFrame& frame, const Pending& cell, OctreeCells& out) {
    const Pruned r = pruned(cell.node, frame.cellBox(cell.corner, cell.size));
    ++out.classified;
    if (r.state == PruneState::Empty) return;
    if (r.state == PruneState::Full) {
        out.full.push_back({cell.corner, cell.size});
        return;
    }
    if (cell.size == 1) {
        out.boundary.push_back({cell.corner, r.node});
        return;
    }
    const int32_t half = cell.size / 2;
    for (int i = 0; i < 8; ++i) {
        const CellCoord c{cell.corner[0] + ((i & 1) ? half : 0),
                          cell.corner[1] + ((i & 2) ? half : 0),
                          cell.corner[2] + ((i & 4) ? half : 0)};
        classify(frame, {c, half, r.node}, out);
    }
}

/// Splits the cube into the cells of a coarse level (classifying on the way) so that the
/// rest can run in parallel, one coarse cell a task.
void splitCoarse(const GridFrame& frame, const Pending& cell, int32_t stopSize,
                 std::vector<Pending>& tasks, OctreeCells& out) {
    if (cell.size <= stopSize) {
        tasks.push_back(cell);
        return;
    }
    const Pruned r = pruned(cell.node, frame.cellBox(cell.corner, cell.size));
    ++out.classified;
    if (r.state == PruneState::Empty) return;
    if (r.state == PruneState::Full) {
        out.full.push_back({cell.corner, cell.size});
        return;
    }
    const int32_t half = cell.size / 2;
    for (int i = 0; i < 8; ++i) {
        const CellCoord c{cell.corner[0] + ((i & 1) ? half : 0),
                          cell.corner[1] + ((i & 2) ? half : 0),
                          cell.corner[2] + ((i & 4) ? half : 0)};
        splitCoarse(frame, {c, half, r.node}, stopSize, tasks, out);
    }
}

}  // namespace

OctreeCells classifyCells(const NodePtr& object, const GridFrame& frame) {
    OctreeCells result;
    std::vector<Pending> tasks;
    // Two levels below the root give up to 64 tasks: enough to balance two to eight threads.
    splitCoarse(frame, {{0, 0, 0}, frame.n, object}, std::max(1, frame.n / 4), tasks, result);
    tbb::enumerable_thread_specific<OctreeCells> parts;
    tbb::parallel_for(size_t(0), tasks.size(), [&](size_t i) { classify(frame, tasks[i], parts.local()); });
    for (OctreeCells& p : parts) {
        result.classified += p.classified;
        result.boundary.insert(result.boundary.end(), std::make_move_iterator(p.boundary.begin()),
                               std::make_move_iterator(p.boundary.end()));
        result.full.insert(result.full.end(), p.full.begin(), p.full.end());
    }
    // Sorted, so the cell indices (and so everything after) do not depend on the threads.
    std::sort(result.boundary.begin(), result.boundary.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    std::sort(result.full.begin(), result.full.end());
    return result;
}

}  // namespace kerf
