// pruned(node, box) on the gyroid and cup models, loaded through lang/: over the ambiguous
// cells of 8³ and 16³ grids on each object's bounds (an octree's levels), the pruned tree
// agrees with the original at random points and on random rays, and the test prints how much
// pruning removes: tape instructions of the implicit leaves and primitives, before and after,
// and (libfive's measure) the instructions of the whole object compiled into one tape
// (csg/tape/tree_tape.h) before and after Tape::simplified over the cell.
#include <catch2/catch.hpp>
#include <cstdio>
#include <string>

#include "csg/tape/tree_tape.h"
#include "lang/compile.h"
#include "util/prune_checks.h"

using namespace kerf;
using namespace kerf::test;

namespace {

struct GridReport {
    int cells = 0, empty = 0, full = 0, partial = 0;
    long tapeBefore = 0, tapeAfter = 0;  ///< summed over the partial cells
    long primitivesBefore = 0, primitivesAfter = 0;
    long treeBefore = 0, treeAfter = 0;  ///< the whole object as one tape
    int failures = 0;
};

/// Every cell of an n³ grid over the object's bounds, pruned and checked.
GridReport pruneGrid(const NodePtr& object, int n, Random& rng) {
    GridReport r;
    const Bounds3 b = object->bounds();
    const Vec3 cell = b.extent() / double(n);
    const std::shared_ptr<const Tape> whole = treeTape(*object);
    std::vector<Choice> choices;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k) {
                const Vec3 lo = b.lo + Vec3(i, j, k) * cell;
                const Bounds3 box{lo, i == n - 1 && j == n - 1 && k == n - 1 ? b.hi : lo + cell};
                const Pruned p = pruned(object, box);
                ++r.cells;
                if (p.state == PruneState::Empty) ++r.empty;
                if (p.state == PruneState::Full) ++r.full;
                if (p.state == PruneState::Partial) {
                    ++r.partial;
                    r.tapeBefore += tapeInstructions(*object);
                    r.tapeAfter += tapeInstructions(*p.node);
                    r.primitivesBefore += object->primitiveCount();
                    r.primitivesAfter += p.node->primitiveCount();
                    whole->evalInterval(Interval(box.lo.x, box.hi.x), Interval(box.lo.y, box.hi.y),
                                        Interval(box.lo.z, box.hi.z), choices);
                    const std::shared_ptr<const Tape> shorter = whole->simplified(choices);
                    r.treeBefore += whole->size();
                    r.treeAfter += shorter->size();
                    // The simplified whole tape is the object's value inside the cell.
                    for (int s = 0; s < 4; ++s) {
                        const Vec3 q = pointIn(box, rng);
                        const double v = object->value(q);
                        if (std::fabs(v) <= kPruneSignSlack) continue;
                        r.failures += (shorter->eval(q) <= 0.0) != (v <= 0.0);
                    }
                }
                r.failures += checkPrunedAgrees(object, p, box, rng, 8, 2);
            }
    return r;
}

void report(const std::string& model, int object, int n, const GridReport& r) {
    const double cells = r.partial > 0 ? r.partial : 1;
    std::printf(
        "pruned %s object %d, %d^3 grid: %d empty, %d full, %d ambiguous; per ambiguous cell "
        "implicit tapes %.1f -> %.1f instructions, primitives %.2f -> %.2f, whole-object tape "
        "%.1f -> %.1f instructions\n",
        model.c_str(), object, n, r.empty, r.full, r.partial, r.tapeBefore / cells,
        r.tapeAfter / cells, r.primitivesBefore / cells, r.primitivesAfter / cells,
        r.treeBefore / cells, r.treeAfter / cells);
}

std::vector<GridReport> pruneModel(const std::string& file, int n) {
    DiagnosticSink sink;
    const std::optional<Scene> scene =
        compileFile(std::string(KERF_SOURCE_DIR) + "/models/" + file, sink);
    INFO(sink.format());
    REQUIRE(scene);
    Random rng(42);
    std::vector<GridReport> out;
    for (size_t i = 0; i < scene->objects.size(); ++i) {
        const NodePtr& object = scene->objects[i];
        if (!object->bounds().finite()) continue;  // the floor: nothing to grid
        out.push_back(pruneGrid(object, n, rng));
        report(file, static_cast<int>(i), n, out.back());
        CHECK(out.back().failures == 0);
        CHECK(out.back().empty + out.back().full + out.back().partial == n * n * n);
    }
    return out;
}

}  // namespace

TEST_CASE("pruned: the gyroid ball over an octree's cells") {
    for (int n : {8, 16}) {
        const std::vector<GridReport> r = pruneModel("gyroid_sphere.kerf", n);
        REQUIRE(r.size() == 1);
        const GridReport& ball = r[0];
        CHECK(ball.partial > 0);
        CHECK(ball.empty > 0);
        // Inside the sphere the intersection loses it. The sheet's tape has no min or max, only
        // an abs, which goes where the gyroid function has one sign over a cell (rare).
        CHECK(ball.primitivesAfter < ball.primitivesBefore);
        CHECK(ball.tapeAfter <= ball.tapeBefore);
        CHECK(ball.treeAfter < ball.treeBefore);
    }
}

TEST_CASE("pruned: the cup over an octree's cells") {
    for (int n : {8, 16}) {
        const std::vector<GridReport> r = pruneModel("cup.kerf", n);
        REQUIRE(r.size() >= 3);  // two cups, the gyroid, the lamp
        // The cup's body and handle are far apart: most ambiguous cells see one of them.
        CHECK(r[0].primitivesAfter < r[0].primitivesBefore / 2);
        CHECK(r[0].treeAfter < r[0].treeBefore / 2);
        CHECK(r[0].empty > 0);
    }
}
