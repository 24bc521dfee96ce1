// A level set's build follows the leaves and tiles its file holds, not its bounding box: two
// small blobs far apart examine a few groups of blocks (the dense build examined every block of
// the box: 512³ for blobs 4,096 apart, 18 s), and rays still find both. Data near the ends of
// the int range is read or refused with its bounds taken in 64 bits (a signed overflow before).
#include "volume/grids/level_set_node.h"
#include "volume/grids/vdb_level_set.h"

#include "util/level_set_files.h"
#include "util/scratch_folder.h"

#include <catch2/catch.hpp>

using namespace kerf;

namespace {

/// A cube of 3³ voxels of value −0.5 at each centre, in a level set of background 3.
test::Grid sparseBlobs(const std::vector<std::array<int, 3>>& centres) {
    test::Grid g;
    g.name = "blobs";
    g.background = 3.0f;
    for (const auto& c : centres)
        for (int i = -1; i <= 1; ++i)
            for (int j = -1; j <= 1; ++j)
                for (int k = -1; k <= 1; ++k)
                    g.values.push_back({{c[0] + i, c[1] + j, c[2] + k}, -0.5f});
    return g;
}

/// The distance along +x from 20 voxels before the blob at c to its surface (index space).
double hitFromTheLeft(const NodePtr& leaf, const std::array<int, 3>& c) {
    TraceContext ctx;
    Boundary hit;
    bool entering = false;
    const Ray ray{Vec3(double(c[0]) - 20.0, c[1], c[2]), Vec3(1.0, 0.0, 0.0)};
    if (!leaf->firstSurface(ray, 0.0, kInf, ctx, hit, entering)) return -1.0;
    return hit.t;
}

std::string levelSetError(const std::string& path) {
    try {
        loadLevelSet(path);
    } catch (const VdbError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST_CASE("LevelSet/two voxels far apart: the build follows the leaves, not the box", "[volume]") {
    test::ScratchFolder dir;
    for (const int apart : {4096, 16384}) {
        CAPTURE(apart);
        const std::array<int, 3> a{0, 0, 0}, b{apart, apart, apart};
        test::writeGrids(dir.file("far.vdb"), {sparseBlobs({a, b})});
        const auto grid = loadLevelSet(dir.file("far.vdb"));
        // Each blob straddles 8 leaves and 8 of OpenVDB's 128³ nodes; each node makes its
        // group and the 7 below it vary: at most 27 groups of 16³ blocks a blob are examined
        // (the dense build examined (apart / 8)³ blocks), and a leaf makes at most 8 bricks.
        CHECK(grid->blocksExamined() <= 2u * 27u * 4096u);
        CHECK(grid->storedGroups() <= 2u * 27u);
        CHECK(grid->brickCount() <= 8u * 16u);
        // The coarse index is dense over the box: 4 bytes a group (2.2 M groups at 16,384).
        CHECK(grid->memoryBytes() < 12u * 1024u * 1024u);
        const NodePtr leaf = levelSetLeaf(grid);
        // −0.5 at x = c − 1, 3 (the background) at c − 2: zero at c − 2 + 6/7, 18 + 6/7 away.
        CHECK(hitFromTheLeft(leaf, a) == Approx(18.0 + 6.0 / 7.0).margin(1e-6));
        CHECK(hitFromTheLeft(leaf, b) == Approx(18.0 + 6.0 / 7.0).margin(1e-6));
    }
}

TEST_CASE("LevelSet/data near the ends of the int range: bounds in 64 bits", "[volume]") {
    test::ScratchFolder dir;
    constexpr int kNear = 2147483647 - 1000;  // within kMaxIndex: read
    for (const int s : {1, -1}) {
        CAPTURE(s);
        const std::array<int, 3> c{s * kNear, s * kNear, s * kNear};
        test::writeGrids(dir.file("edge.vdb"), {sparseBlobs({c})});
        const auto grid = loadLevelSet(dir.file("edge.vdb"));
        CHECK(hitFromTheLeft(levelSetLeaf(grid), c) == Approx(18.0 + 6.0 / 7.0).margin(1e-6));
    }
    // Voxels at ±(2^31 − 2): refused by their coordinates (those of their 8³ leaves), nothing
    // computed past the int range.
    constexpr int kEnd = 2147483647 - 1;
    test::writeGrids(dir.file("ends.vdb"), {sparseBlobs({{-kEnd + 1, 0, 0}, {kEnd - 1, 0, 0}})});
    CHECK(levelSetError(dir.file("ends.vdb")) ==
          "grid 'blobs' has data at index -2147483648 along x, beyond ±2147483136 (kerf's range "
          "for a level set's index coordinates)");
    // Two blobs 2^25 apart along each axis: a box of 2^54 groups, refused by its size.
    test::writeGrids(dir.file("wide.vdb"), {sparseBlobs({{0, 0, 0}, {1 << 25, 1 << 25, 1 << 25}})});
    CHECK_THAT(levelSetError(dir.file("wide.vdb")),
               Catch::StartsWith("grid 'blobs''s data spans a box of 33554448 x 33554448 x "
                                 "33554448 voxels (its leaves and tiles); a level set's box may "
                                 "hold at most 4194304 blocks of 128³ voxels"));
}
