// Hidden benchmark (tag [.bench], never run by ctest): 10⁶ box evaluations of the gyroid tape
// as the octree makes them (the eight children of a cell, four per call), by evalInterval per
// box, evalInterval4's scalar path and its AVX2 path. Prints the median of 5 timings of each and
// how many of the 10⁶ results differ from evalInterval's bits (they must not: the tests say so).
//   build/tests/kerf_csg_tests "[.bench]"
// KERF_BENCH_BOXES=n changes the count; KERF_BENCH_ONLY=ref|scalar|avx2 runs one variant once
// (for callgrind: --toggle-collect='kerf::Tape::evalInterval*').
#include "csg/tape/tape.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <random>
#include <string>

using namespace kerf;

namespace {

std::shared_ptr<const Tape> gyroid() {
    ExprGraph g;
    const ExprId k = g.constant(2.0 * M_PI);
    const ExprId u = g.binary(Op::Mul, k, g.x()), v = g.binary(Op::Mul, k, g.y()),
                 w = g.binary(Op::Mul, k, g.z());
    auto term = [&](ExprId a, ExprId b) {
        return g.binary(Op::Mul, g.unary(Op::Sin, a), g.unary(Op::Cos, b));
    };
    return Tape::compile(g,
                         g.binary(Op::Add, g.binary(Op::Add, term(u, v), term(v, w)), term(w, u)));
}

struct Boxes {
    std::vector<Interval> x, y, z;  ///< groups of four: children 0–3 or 4–7 of one cell
};

/// The children of random cells of a 6-unit octree at depths 1 to 9, as the octree asks.
Boxes octreeChildren(size_t count) {
    std::mt19937_64 rng(5);
    Boxes b;
    while (b.x.size() < count) {
        const int depth = std::uniform_int_distribution<int>(1, 9)(rng);
        const double cell = std::ldexp(6.0, -depth), half = 0.5 * cell;
        const int cells = 1 << depth;
        std::uniform_int_distribution<int> index(0, cells - 1);
        const double ox = -3.0 + index(rng) * cell, oy = -3.0 + index(rng) * cell,
                     oz = -3.0 + index(rng) * cell;
        for (int c = 0; c < 8; ++c) {
            const double x0 = ox + (c & 1) * half, y0 = oy + (c >> 1 & 1) * half,
                         z0 = oz + (c >> 2 & 1) * half;
            b.x.push_back({x0, x0 + half});
            b.y.push_back({y0, y0 + half});
            b.z.push_back({z0, z0 + half});
        }
    }
    b.x.resize(count), b.y.resize(count), b.z.resize(count);
    return b;
}

enum class Variant { Reference, Scalar, Avx2 };

void run(const Tape& f, const Boxes& b, Variant v, std::vector<Interval>& out) {
    const size_t n = b.x.size();
    out.resize(n);
    if (v == Variant::Reference) {
        for (size_t i = 0; i < n; ++i) out[i] = f.evalInterval(b.x[i], b.y[i], b.z[i]);
        return;
    }
    const Tape::Lanes4 lanes = v == Variant::Scalar ? Tape::Lanes4::Scalar : Tape::Lanes4::Avx2;
    for (size_t i = 0; i + 4 <= n; i += 4)
        f.evalInterval4(&b.x[i], &b.y[i], &b.z[i], &out[i], lanes);
}

size_t mismatches(const std::vector<Interval>& a, const std::vector<Interval>& b) {
    size_t n = 0;
    for (size_t i = 0; i < a.size(); ++i)
        n += std::memcmp(&a[i].lo, &b[i].lo, sizeof(double)) != 0 ||
             std::memcmp(&a[i].hi, &b[i].hi, sizeof(double)) != 0 || a[i].maybeNan != b[i].maybeNan;
    return n;
}

}  // namespace

TEST_CASE("bench: Tape::evalInterval4 on the gyroid over octree children", "[.bench]") {
    const char* boxesEnv = std::getenv("KERF_BENCH_BOXES");
    const size_t count = (boxesEnv ? std::stoul(boxesEnv) : 1000000) / 4 * 4;
    const char* only = std::getenv("KERF_BENCH_ONLY");
    const auto f = gyroid();
    const Boxes boxes = octreeChildren(count);
    std::vector<Interval> reference, out;
    if (only) {
        const std::string o = only;
        run(*f, boxes,
            o == "ref"      ? Variant::Reference
            : o == "scalar" ? Variant::Scalar
                            : Variant::Avx2,
            out);
        std::cout << "ran " << o << " over " << count << " boxes\n";
        return;
    }
    run(*f, boxes, Variant::Reference, reference);
    std::cout << "gyroid tape of " << f->size() << " instructions, " << count << " boxes"
              << (Tape::hasAvx2() ? "" : " (no AVX2: the avx2 row runs the scalar path)") << "\n";
    double referenceMedian = 0.0;
    for (Variant v : {Variant::Reference, Variant::Scalar, Variant::Avx2}) {
        std::vector<double> ms;
        for (int rep = 0; rep < 5; ++rep) {
            const auto t0 = std::chrono::steady_clock::now();
            run(*f, boxes, v, out);
            ms.push_back(
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                    .count());
        }
        std::sort(ms.begin(), ms.end());
        if (v == Variant::Reference) referenceMedian = ms[2];
        const char* name = v == Variant::Reference ? "evalInterval x4"
                           : v == Variant::Scalar  ? "evalInterval4 scalar"
                                                   : "evalInterval4 avx2";
        std::cout << name << ": median " << ms[2] << " ms (min " << ms[0] << ", max " << ms[4]
                  << "), " << 1e6 * ms[2] / double(count) << " ns/box, speed-up "
                  << referenceMedian / ms[2]
                  << ", results differing from evalInterval: " << mismatches(reference, out)
                  << "\n";
        CHECK(mismatches(reference, out) == 0);
    }
}
