// The bricked grid against plain x-fastest arrays: the lookup-table addressing for every voxel
// of small odd-sized grids, trilinear samples against a flat reference (bit for bit: the same
// lerp order, written out again here), sparse allocation counted, and range bounds checked by
// brute force.
#include "volume/grids/brick_grid.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <set>
#include <vector>

using namespace kerf;

namespace {

const BrickLayout kLayouts[] = {{1, 0}, {1, 1}, {2, 1}, {3, 0}, {2, 2}, {3, 3}};
const glm::ivec3 kSizes[] = {{1, 1, 1}, {5, 7, 9}, {13, 3, 11}, {17, 19, 2}, {9, 9, 9}};

/// A flat x-fastest array of random floats and the same values in a bricked grid.
struct Pair {
    glm::ivec3 s;
    std::vector<float> flat;
    BrickGrid<float> grid;
    Pair(glm::ivec3 size, BrickLayout layout, unsigned seed) : s(size), grid(size, -7.0f, layout) {
        std::mt19937 rng(seed);
        std::uniform_real_distribution<float> u(-3.0f, 5.0f);
        flat.resize(std::size_t(s.x) * s.y * s.z);
        for (float& v : flat) v = u(rng);
        for (int z = 0; z < s.z; ++z)
            for (int y = 0; y < s.y; ++y)
                for (int x = 0; x < s.x; ++x) grid.set(x, y, z, at(x, y, z));
    }
    float at(int x, int y, int z) const {
        return flat[std::size_t(x) + std::size_t(s.x) * (y + std::size_t(s.y) * z)];
    }

    /// Trilinear on the flat array: the cell of floor(u) clamped to the last cell, constant
    /// beyond the edges, lerps along x, then y, then z.
    double reference(double px, double py, double pz) const {
        const double p[3] = {px, py, pz};
        int i0[3], i1[3];
        double t[3];
        for (int a = 0; a < 3; ++a) {
            const double c = std::min(std::max(p[a], 0.0), double(s[a] - 1));
            const int i = std::min(int(std::floor(c)), std::max(s[a] - 2, 0));
            i0[a] = i;
            i1[a] = std::min(i + 1, s[a] - 1);
            t[a] = c - i;
        }
        auto v = [&](int dx, int dy, int dz) {
            return double(at(dx ? i1[0] : i0[0], dy ? i1[1] : i0[1], dz ? i1[2] : i0[2]));
        };
        auto lerp = [](double a, double b, double w) { return a + w * (b - a); };
        const double y0 =
            lerp(lerp(v(0, 0, 0), v(1, 0, 0), t[0]), lerp(v(0, 1, 0), v(1, 1, 0), t[0]), t[1]);
        const double y1 =
            lerp(lerp(v(0, 0, 1), v(1, 0, 1), t[0]), lerp(v(0, 1, 1), v(1, 1, 1), t[0]), t[1]);
        return lerp(y0, y1, t[2]);
    }
};

}  // namespace

TEST_CASE("BrickIndex::key") {
    for (const BrickLayout& l : kLayouts)
        for (const glm::ivec3& s : kSizes) {
            CAPTURE(l.brickLog2, l.macroLog2, s.x, s.y, s.z);
            const BrickIndex ix(s, l);
            const int n = 1 << l.brickLog2, m = 1 << l.macroLog2, side = n * m;
            const glm::ivec3 mc = ix.macroCount();
            CHECK(mc == (s + side - 1) / side);
            std::set<std::uint64_t> seen;
            for (int z = 0; z < s.z; ++z)
                for (int y = 0; y < s.y; ++y)
                    for (int x = 0; x < s.x; ++x) {
                        // The textbook address written with divisions: macrobrick x-fastest,
                        // brick x-fastest inside it, voxel x-fastest inside the brick.
                        const glm::ivec3 v(x, y, z), macro = v / side, brick = (v % side) / n,
                                                     in = v % n;
                        const std::uint64_t macroNumber =
                            macro.x +
                            std::uint64_t(mc.x) * (macro.y + std::uint64_t(mc.y) * macro.z);
                        const std::uint64_t offset =
                            std::uint64_t(n) * n * n * (brick.x + m * (brick.y + m * brick.z)) +
                            in.x + n * (in.y + std::uint64_t(n) * in.z);
                        const std::uint64_t k = ix.key(x, y, z);
                        REQUIRE(BrickIndex::macroOf(k) == macroNumber);
                        REQUIRE(BrickIndex::offsetOf(k) == offset);
                        REQUIRE(offset < ix.macroVoxels());
                        seen.insert(k);
                    }
            CHECK(seen.size() == std::size_t(s.x) * s.y * s.z);  // no two voxels share a slot
        }
    CHECK_THROWS_AS(BrickIndex({4, 4, 4}, {0, 3}), std::invalid_argument);
    CHECK_THROWS_AS(BrickIndex({4, 4, 4}, {6, 3}), std::invalid_argument);
    CHECK_THROWS_AS(BrickIndex({4, 4, 4}, {5, 6}), std::invalid_argument);
    CHECK_THROWS_AS(BrickIndex({4, 0, 4}, {3, 3}), std::invalid_argument);
}

TEST_CASE("BrickGrid::get") {
    // Each voxel holds its plain x-fastest index; every read must give it back.
    for (const BrickLayout& l : kLayouts)
        for (const glm::ivec3& s : kSizes) {
            CAPTURE(l.brickLog2, l.macroLog2, s.x, s.y, s.z);
            BrickGrid<int> g(s, -1, l);
            for (int z = 0; z < s.z; ++z)
                for (int y = 0; y < s.y; ++y)
                    for (int x = 0; x < s.x; ++x) g.set(x, y, z, x + s.x * (y + s.y * z));
            for (int z = 0; z < s.z; ++z)
                for (int y = 0; y < s.y; ++y)
                    for (int x = 0; x < s.x; ++x)
                        REQUIRE(g.get(x, y, z) == x + s.x * (y + s.y * z));
        }
}

TEST_CASE("BrickGrid::sample") {
    // Bit for bit against the flat reference, at random points, at points on brick faces and
    // next to them (where the fast path ends), and beyond the edges.
    unsigned seed = 1;
    for (const BrickLayout& l : kLayouts)
        for (const glm::ivec3& s : kSizes) {
            CAPTURE(l.brickLog2, l.macroLog2, s.x, s.y, s.z);
            const Pair p(s, l, seed++);
            std::mt19937 rng(seed);
            const int n = 1 << l.brickLog2;
            std::vector<double> along[3];
            for (int a = 0; a < 3; ++a) {
                std::uniform_real_distribution<double> u(-1.5, s[a] + 0.5);
                for (int k = 0; k < 40; ++k) along[a].push_back(u(rng));
                for (int b = 0; b <= s[a]; b += n)
                    for (double d : {-1.0, -0.5, -0x1p-30, 0.0, 0x1p-30, 0.25, 1.0})
                        along[a].push_back(b + d);
                along[a].push_back(s[a] - 1);
            }
            std::uniform_int_distribution<std::size_t> pick(0, 1 << 30);
            for (int k = 0; k < 4000; ++k) {
                const double x = along[0][pick(rng) % along[0].size()];
                const double y = along[1][pick(rng) % along[1].size()];
                const double z = along[2][pick(rng) % along[2].size()];
                CAPTURE(x, y, z);
                REQUIRE(p.grid.sample(x, y, z) == p.reference(x, y, z));
                double g[3];
                REQUIRE(p.grid.sampleGradient(x, y, z, g) == p.reference(x, y, z));
            }
        }
}

TEST_CASE("BrickGrid::sampleGradient") {
    // Inside a cell the interpolant is linear along each axis: the gradient equals the
    // difference quotient across the cell's faces (long double reference, no step error).
    const glm::ivec3 s(11, 9, 10);
    const Pair p(s, {2, 1}, 99);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int k = 0; k < 2000; ++k) {
        const glm::ivec3 c(int(u(rng) * (s.x - 1)), int(u(rng) * (s.y - 1)),
                           int(u(rng) * (s.z - 1)));
        const double t[3] = {u(rng), u(rng), u(rng)};
        const double q[3] = {c.x + t[0], c.y + t[1], c.z + t[2]};
        double g[3];
        p.grid.sampleGradient(q[0], q[1], q[2], g);
        for (int a = 0; a < 3; ++a) {
            double lo[3] = {q[0], q[1], q[2]}, hi[3] = {q[0], q[1], q[2]};
            lo[a] = c[a];
            hi[a] = c[a] + 1;
            const double expected =
                p.reference(hi[0], hi[1], hi[2]) - p.reference(lo[0], lo[1], lo[2]);
            CHECK(g[a] == Approx(expected).margin(1e-12));
        }
    }
    // Beyond an edge the field is constant along that axis.
    double g[3];
    p.grid.sampleGradient(-2.0, 3.5, 4.5, g);
    CHECK(g[0] == 0.0);
    CHECK(g[1] != 0.0);
}

TEST_CASE("BrickGrid::allocatedMacrobricks") {
    // 100³ voxels in macrobricks of 16³ (bricks of 4³, 4³ of them): 7³ = 343 macrobricks.
    BrickGrid<float> g({100, 100, 100}, 0.5f, {2, 2});
    REQUIRE(g.index().macroTotal() == 343);
    CHECK(g.allocatedMacrobricks() == 0);
    CHECK(g.get(50, 60, 70) == 0.5f);
    CHECK(g.sample(50.3, 60.2, 70.9) == 0.5);
    g.set(0, 0, 0, 1.0f);
    g.set(15, 15, 15, 2.0f);  // same macrobrick
    g.set(16, 0, 0, 3.0f);    // its x neighbour
    g.set(99, 99, 99, 4.0f);  // the last (partial) one
    CHECK(g.allocatedMacrobricks() == 3);
    CHECK(g.get(16, 0, 0) == 3.0f);
    CHECK(g.get(17, 0, 0) == 0.5f);
    CHECK(g.get(99, 99, 99) == 4.0f);

    // fill() keeps only the macrobricks holding a value other than the background: a ball of
    // radius 20 around (30, 30, 30) meets the macrobricks whose box is within 20 of it.
    BrickGrid<float> f({100, 100, 100}, 0.0f, {2, 2});
    auto inBall = [](int x, int y, int z) {
        return (x - 30) * (x - 30) + (y - 30) * (y - 30) + (z - 30) * (z - 30) <= 400;
    };
    f.fill([&](int x, int y, int z) { return inBall(x, y, z) ? 1.0f : 0.0f; });
    std::size_t expected = 0;
    for (int mz = 0; mz < 7; ++mz)
        for (int my = 0; my < 7; ++my)
            for (int mx = 0; mx < 7; ++mx) {
                bool any = false;
                for (int z = mz * 16; z < std::min(100, mz * 16 + 16) && !any; ++z)
                    for (int y = my * 16; y < std::min(100, my * 16 + 16) && !any; ++y)
                        for (int x = mx * 16; x < std::min(100, mx * 16 + 16) && !any; ++x)
                            any = inBall(x, y, z);
                expected += any;
                CHECK(f.macroAllocated(f.index().macroNumber(mx, my, mz)) == any);
            }
    CHECK(f.allocatedMacrobricks() == expected);
    CHECK(expected < 343 / 4);
    for (int z = 0; z < 100; z += 3)
        for (int y = 0; y < 100; y += 5)
            for (int x = 0; x < 100; ++x)
                REQUIRE(f.get(x, y, z) == (inBall(x, y, z) ? 1.0f : 0.0f));
}

TEST_CASE("BrickGrid::rangeOfVoxels") {
    // The bound holds every voxel of random boxes, after set() (widened bounds) and after
    // refreshRanges() (exact per brick), and is exact for a box of whole bricks after a refresh.
    const glm::ivec3 s(37, 29, 41);
    Pair p(s, {2, 1}, 7);
    std::mt19937 rng(11);
    auto check = [&](const BrickGrid<float>& g) {
        for (int k = 0; k < 300; ++k) {
            glm::ivec3 lo, hi;
            for (int a = 0; a < 3; ++a) {
                std::uniform_int_distribution<int> u(-3, s[a] + 2);
                lo[a] = u(rng);
                hi[a] = u(rng);
                if (lo[a] > hi[a]) std::swap(lo[a], hi[a]);
            }
            const auto r = g.rangeOfVoxels(lo, hi);
            const glm::ivec3 a = glm::clamp(lo, glm::ivec3(0), s - 1),
                             b = glm::clamp(hi, glm::ivec3(0), s - 1);
            for (int z = a.z; z <= b.z; ++z)
                for (int y = a.y; y <= b.y; ++y)
                    for (int x = a.x; x <= b.x; ++x) {
                        REQUIRE(r.first <= g.get(x, y, z));
                        REQUIRE(g.get(x, y, z) <= r.second);
                    }
        }
    };
    check(p.grid);
    for (int k = 0; k < 200; ++k)
        p.grid.set(rng() % s.x, rng() % s.y, rng() % s.z, float(rng() % 100) - 50.0f);
    check(p.grid);
    p.grid.refreshRanges();
    check(p.grid);
    float lo = p.grid.get(4, 8, 12), hi = lo;
    for (int z = 12; z < 24; ++z)
        for (int y = 8; y < 16; ++y)
            for (int x = 4; x < 8; ++x) {
                lo = std::min(lo, p.grid.get(x, y, z));
                hi = std::max(hi, p.grid.get(x, y, z));
            }
    const auto r = p.grid.rangeOfVoxels({4, 8, 12}, {7, 15, 23});
    CHECK(r.first == lo);
    CHECK(r.second == hi);
}

TEST_CASE("BrickGrid::prefetchBrick") {
    // A hint only: it names the brick holding the (clamped) voxel and changes nothing.
    const glm::ivec3 s(37, 29, 41);
    Pair p(s, {2, 1}, 13);
    const BrickIndex& ix = p.grid.index();
    CHECK(p.grid.prefetchBrick(5, 6, 7) == ix.brickNumber(1, 1, 1));
    CHECK(p.grid.prefetchBrick(-3, 28, 100) == ix.brickNumber(0, 7, 10));
    CHECK(p.grid.prefetchBrick(36, 0, 40) == ix.brickNumber(9, 0, 10));
    for (int z = 0; z < s.z; ++z)
        for (int y = 0; y < s.y; ++y)
            for (int x = 0; x < s.x; ++x) REQUIRE(p.grid.get(x, y, z) == p.at(x, y, z));
}
