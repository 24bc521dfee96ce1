// Coarse-to-fine classification of an object's octree cells by interval pruning.
#include "volume/octree/octree_build.h"

#include "csg/tree/prune.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <unordered_map>

namespace kerf {

namespace {

struct Pending {
    CellCoord corner;
    int32_t size;
    NodePtr node;  ///< the parent's pruned tree: equal to the object inside this cell
};

CellCoord childCorner(const CellCoord& c, int32_t half, int i) {
    return {c[0] + ((i & 1) ? half : 0), c[1] + ((i & 2) ? half : 0), c[2] + ((i & 4) ? half : 0)};
}

/// Continues from a cell whose pruning `r` is known: while it is larger than `stopSize` and the
/// surface may cross it, its 8 children are pruned together (prunedMany) and classified in
/// turn (depth first). Cells of stopSize the surface may cross go to `reached`.
template <class Reached, class Full>
void classifyFrom(const GridFrame& frame, const CellCoord& corner, int32_t size, const Pruned& r,
                  int32_t stopSize, uint64_t& classified, Reached&& reached, Full&& full) {
    if (r.state == PruneState::Empty) return;
    if (r.state == PruneState::Full) return full(corner, size);
    if (size == stopSize) return reached(corner, r.node);
    const int32_t half = size / 2;
    Bounds3 boxes[8];
    Pruned kids[8];
    for (int i = 0; i < 8; ++i) boxes[i] = frame.cellBox(childCorner(corner, half, i), half);
    prunedMany(r.node, boxes, 8, kids);
    classified += 8;
    for (int i = 0; i < 8; ++i)
        classifyFrom(frame, childCorner(corner, half, i), half, kids[i], stopSize, classified,
                     reached, full);
}

/// Classifies one cell (pruning its parent's tree over it) and what lies below it.
template <class Reached, class Full>
void classify(const GridFrame& frame, const Pending& cell, int32_t stopSize, uint64_t& classified,
              Reached&& reached, Full&& full) {
    const Pruned r = pruned(cell.node, frame.cellBox(cell.corner, cell.size));
    ++classified;
    classifyFrom(frame, cell.corner, cell.size, r, stopSize, classified, reached, full);
}

}  // namespace

CoarseCells classifyCoarse(const NodePtr& object, const GridFrame& frame) {
    CoarseCells result;
    // Down to cells of a quarter of the cube serially (at most 73 classifications), then one
    // task per such cell: up to 64 tasks, enough to balance two to eight threads.
    std::vector<Pending> tasks;
    const int32_t taskSize = std::max(kBrickCells, frame.n / 4);
    auto addFull = [&](const CellCoord& c, int32_t size) { result.full.push_back({c, size}); };
    classify(
        frame, {{0, 0, 0}, frame.n, object}, taskSize, result.classified,
        [&](const CellCoord& c, const NodePtr& n) {
            tasks.push_back({c, taskSize, n});
        },
        addFull);
    struct Part {
        CoarseCells cells;
    };
    tbb::enumerable_thread_specific<Part> parts;
    tbb::parallel_for(size_t(0), tasks.size(), [&](size_t i) {
        CoarseCells& out = parts.local().cells;
        const Pending& t = tasks[i];
        if (t.size == kBrickCells) {  // the task is a brick already
            out.bricks.push_back({t.corner, t.node});
            return;
        }
        // The task's own cell was classified above (the surface may cross it); its children
        // from here.
        classifyFrom(
            frame, t.corner, t.size, Pruned{PruneState::Partial, t.node}, kBrickCells,
            out.classified,
            [&](const CellCoord& c, const NodePtr& n) {
                out.bricks.push_back({c, n});
            },
            [&](const CellCoord& c, int32_t size) {
                out.full.push_back({c, size});
            });
    });
    for (Part& p : parts) {
        result.classified += p.cells.classified;
        result.bricks.insert(result.bricks.end(), std::make_move_iterator(p.cells.bricks.begin()),
                             std::make_move_iterator(p.cells.bricks.end()));
        result.full.insert(result.full.end(), p.cells.full.begin(), p.cells.full.end());
    }
    // Sorted, so brick indices (and so everything after) do not depend on the threads.
    std::sort(result.bricks.begin(), result.bricks.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    std::sort(result.full.begin(), result.full.end());
    return result;
}

void classifyBrick(const GridFrame& frame, const CellCoord& corner, const NodePtr& node,
                   BrickContent& out) {
    std::unordered_map<const Node*, uint16_t> slot;  // 1 + index in out.nodes
    auto local = [&](const CellCoord& c, int a) { return c[a] - corner[a]; };
    // The brick itself was classified with the coarse levels (the surface may cross it).
    classifyFrom(
        frame, corner, kBrickCells, Pruned{PruneState::Partial, node}, 1, out.classified,
        [&](const CellCoord& c, const NodePtr& n) {
            auto [it, added] = slot.emplace(n.get(), uint16_t(out.nodes.size() + 1));
            if (added) out.nodes.push_back(n);
            out.cell[size_t(BrickContent::index(local(c, 0), local(c, 1), local(c, 2)))] =
                it->second;
            ++out.boundaryCells;
        },
        [&](const CellCoord& c, int32_t size) {
            for (int x = 0; x < size; ++x)
                for (int y = 0; y < size; ++y)
                    for (int z = 0; z < size; ++z)
                        out.full[size_t(BrickContent::index(local(c, 0) + x, local(c, 1) + y,
                                                            local(c, 2) + z))] = true;
        });
}

}  // namespace kerf
