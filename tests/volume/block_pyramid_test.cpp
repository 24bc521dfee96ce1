// The sparse min/max pyramid of fog volumes (volume/grids/block_pyramid.h): every range holds
// the exact range of the blocks it covers (brute force over random sparse blocks and tiles),
// is exact where the box is one held block, and memory follows the data: fog files whose two
// voxels lie 2^25 apart, or at ±(2^31 − 2), once crashed a dense pyramid (issue 24) and now
// load with a handful of cells.
#include "volume/grids/block_pyramid.h"

#include "volume/grids/vdb_fog.h"

#include "../app/kerf_runner.h"
#include "util/level_set_files.h"

#include <catch2/catch.hpp>

#include <map>
#include <random>

using namespace kerf;
using namespace kerf::test;

namespace {

/// What each block holds, written out: the oracle.
struct DenseBlocks {
    float background;
    std::map<BlockCoord, std::pair<float, float>> held;
    std::pair<float, float> at(const BlockCoord& b) const {
        const auto it = held.find(b);
        return it == held.end() ? std::pair{background, background} : it->second;
    }
};

int floorDiv(int v, int d) { return v >= 0 ? v / d : -((-v + d - 1) / d); }

}  // namespace

TEST_CASE("BlockPyramid::range holds every block's values and is exact for one held block") {
    std::mt19937 rng(11);
    for (const float background : {0.0f, 0.25f}) {
        const BlockCoord lo{-20, -9, 3}, hi{17, 30, 40};
        BlockPyramid pyramid(background, lo, hi);  // dense layout: the box is small
        BlockPyramid sparse(background, lo, hi, BlockPyramid::Layout::Sparse);
        DenseBlocks oracle{background, {}};
        std::uniform_int_distribution<int> x(lo[0], hi[0]), y(lo[1], hi[1]), z(lo[2], hi[2]);
        std::uniform_real_distribution<float> v(0.0f, 2.0f);
        for (int n = 0; n < 400; ++n) {
            const BlockCoord b{x(rng), y(rng), z(rng)};
            if (oracle.held.count(b)) continue;
            const float a = v(rng), c = v(rng);
            pyramid.addBlock(b, std::min(a, c), std::max(a, c));
            sparse.addBlock(b, std::min(a, c), std::max(a, c));
            oracle.held[b] = {std::min(a, c), std::max(a, c)};
        }
        // Two constant tiles of 4³ blocks (level 2) in space no block took.
        for (const BlockCoord t : {BlockCoord{-5, 2, 2}, BlockCoord{3, 6, 8}}) {
            bool free = true;
            for (const auto& [b, r] : oracle.held)
                if (floorDiv(b[0], 4) == t[0] && floorDiv(b[1], 4) == t[1] &&
                    floorDiv(b[2], 4) == t[2])
                    free = false;
            if (!free) continue;
            const float value = v(rng);
            pyramid.addTile(2, t, value);
            sparse.addTile(2, t, value);
            for (int i = 0; i < 4; ++i)
                for (int j = 0; j < 4; ++j)
                    for (int k = 0; k < 4; ++k)
                        oracle.held[{4 * t[0] + i, 4 * t[1] + j, 4 * t[2] + k}] = {value, value};
        }
        pyramid.finish();
        sparse.finish();
        std::uniform_int_distribution<int> w(0, 12);
        for (int n = 0; n < 2000; ++n) {
            const BlockCoord q0{x(rng) - 2, y(rng) - 2, z(rng) - 2};
            const BlockCoord q1{q0[0] + w(rng), q0[1] + w(rng), q0[2] + w(rng)};
            float elo = kInf, ehi = -kInf;
            for (int i = q0[0]; i <= q1[0]; ++i)
                for (int j = q0[1]; j <= q1[1]; ++j)
                    for (int k = q0[2]; k <= q1[2]; ++k) {
                        const auto r = oracle.at({i, j, k});
                        elo = std::min(elo, r.first), ehi = std::max(ehi, r.second);
                    }
            const Interval r = pyramid.range(q0, q1);
            INFO("blocks " << q0[0] << "," << q0[1] << "," << q0[2] << " .. " << q1[0] << ","
                           << q1[1] << "," << q1[2] << ": [" << r.lo << ", " << r.hi << "], exact ["
                           << elo << ", " << ehi << "]");
            REQUIRE(r.lo <= elo);
            REQUIRE(r.hi >= ehi);
            // Both layouts give the same bits.
            const Interval rs = sparse.range(q0, q1);
            REQUIRE(rs.lo == r.lo);
            REQUIRE(rs.hi == r.hi);
        }
        for (const auto& [b, held] : oracle.held) {
            const Interval r = pyramid.range(b, b);
            REQUIRE(r.lo == held.first);
            REQUIRE(r.hi == held.second);
        }
    }
}

TEST_CASE("BlockPyramid cells follow the data, not the box") {
    const BlockCoord far{(1 << 22) - 2, (1 << 22) - 2, (1 << 20) - 2};
    BlockPyramid pyramid(0.0f, {0, 0, 0}, far);
    pyramid.addBlock({0, 0, 0}, 0.5f, 1.0f);
    pyramid.addBlock(far, 2.0f, 3.0f);
    pyramid.finish();
    CHECK(pyramid.levels() == 23);
    CHECK(pyramid.cells() <= size_t(2 * pyramid.levels()));
    CHECK(pyramid.range({0, 0, 0}, {0, 0, 0}).hi == 1.0);
    CHECK(pyramid.range(far, far).lo == 2.0);
    // Between them: nothing but background.
    const Interval middle = pyramid.range({1000, 1000, 1000}, {1003, 1003, 1003});
    CHECK(middle.lo == 0.0);
    CHECK(middle.hi == 0.0);
    CHECK(pyramid.whole().hi == 3.0);
}

TEST_CASE("vdb_fog/two voxels far apart load in memory that follows them") {
    struct Case {
        const char* name;
        std::array<int, 3> a, b;
    };
    const int big = (1 << 25) - 16, edge = 2147483646;  // 2^31 − 2
    for (const Case& c : {Case{"2^25 apart", {0, 0, 0}, {big, big, (1 << 23) - 16}},
                          Case{"at the int range", {-edge, -edge, -edge}, {edge, edge, edge}}}) {
        INFO(c.name);
        TempDir dir;
        Grid g;
        g.kind = Grid::Kind::FogVolume;
        g.name = "density";
        g.voxel = 1.0;
        g.values.push_back({c.a, 0.5f});
        g.values.push_back({c.b, 0.75f});
        const std::string path = dir.file("far.vdb");
        writeGrids(path, {g});
        const VdbFog fog = loadVdbFog(path, "");
        const ScalarField& f = *fog.density;
        const Vec3 pa(c.a[0], c.a[1], c.a[2]), pb(c.b[0], c.b[1], c.b[2]);
        CHECK(f.value(pa) == Approx(0.5));
        CHECK(f.value(pb) == Approx(0.75));
        const Interval near =
            f.range(Interval(pb.x - 0.5, pb.x + 0.5), Interval(pb.y - 0.5, pb.y + 0.5),
                    Interval(pb.z - 0.5, pb.z + 0.5));
        CHECK(near.hi >= 0.75);
        CHECK(near.hi <= 0.75 + 1e-6);
        const Vec3 mid = 0.5 * (pa + pb) + Vec3(0.5);
        const Interval empty = f.range(Interval(mid.x, mid.x + 8), Interval(mid.y, mid.y + 8),
                                       Interval(mid.z, mid.z + 8));
        CHECK(empty.hi == 0.0);
    }
}
