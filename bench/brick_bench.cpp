// Two-level bricked storage against a flat x-fastest array and OpenVDB's ValueAccessor, on the
// same data in one process (issue 14 §1; docs/BENCHMARKS.md, "Bricked storage"). A field of
// N³ floats (default 512³, 512 MiB per copy; three copies alive at most) holding a smooth
// noise-like function (a sum of products of sines with random frequencies and phases) is read
// by each storage in five ways:
//   - march: lines through the cube along random directions, a trilinear sample every half
//     voxel, summed; and the same with a prefetch ahead along the line (the flat array: the 4
//     lines of the stencil --ahead-flat voxels ahead; the bricked grid: the whole brick
//     --ahead-brick voxels ahead, BrickGrid::prefetchBrick, once per brick);
//   - march, camera: the same on a volume renderer's coherent rays (--camera P: P² parallel
//     rays one voxel apart along an oblique direction, in 8 × 8 tiles), with and without prefetch;
//   - points: random voxels, summed;
//   - samples: trilinear samples at random points, summed;
//   - slice x / y / z: whole planes normal to x, y, z, every voxel read, summed.
// The three storages read the same floats and interpolate with the same formula
// (volume/grids/brick_grid.h trilinear(), the same cell choice), so their sums must agree bit for
// bit; OpenVDB's own BoxSampler (its own formula) is timed too on the march, with its
// difference from the flat sum. Timings: median of --runs of thread CPU time and of wall time,
// the storages interleaved within each run so that a busy machine slows all of them alike.
//
// Build: cmake -S bench -B build/bench-reference
//        cmake --build build/bench-reference --target kerf_brick_bench
// Run:   kerf_brick_bench [--size N] [--runs R] [--rays K] [--points K] [--slices K] [--brick B]
//        [--macro M] [--only WORKLOAD] [--ahead-flat V] [--ahead-brick V] [--camera P]
//        (B, M: log2 of the brick side and of the macrobrick side in bricks; V: look-ahead in
//        voxels)
#include <openvdb/openvdb.h>
#include <openvdb/tools/Dense.h>
#include <openvdb/tools/Interpolation.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "volume/grids/brick_grid.h"

using namespace kerf;

namespace {

struct Options {
    int size = 512;        ///< N: the field is N³ voxels
    int runs = 5;          ///< median of this many
    int rays = 20000;      ///< lines of the march
    int points = 8000000;  ///< random voxels (and as many random trilinear samples)
    int slices = 8;        ///< planes per axis
    BrickLayout layout{3, 3};
    std::string only;        ///< run only the workloads whose name starts with this
    int aheadFlat = 8;       ///< march with prefetch: the flat array's look-ahead, in voxels
    int aheadBrick = 8;      ///< and the bricked grid's
    int cameraPixels = 128;  ///< the coherent march: this many² parallel rays, one voxel apart
};

double thread_seconds() {
    timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/// splitmix64: the same stream for every storage.
struct Rng {
    std::uint64_t s;
    std::uint64_t next() {
        std::uint64_t z = (s += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    int below(int n) { return int(((next() >> 32) * std::uint64_t(n)) >> 32); }
    double unit() { return double(next() >> 11) * 0x1p-53; }
};

// ---- the three storages, each with voxel() and sample() ----

struct Flat {
    const float* d;
    int n;
    float voxel(int x, int y, int z) const {
        return d[size_t(x) + size_t(n) * (size_t(y) + size_t(n) * size_t(z))];
    }
    double sample(double x, double y, double z) const {
        const SampleCell cx = sampleCell(x, n), cy = sampleCell(y, n), cz = sampleCell(z, n);
        const size_t sy = size_t(n), sz = size_t(n) * size_t(n);
        const float* p = d + size_t(cx.i) + sy * size_t(cy.i) + sz * size_t(cz.i);
        const size_t dx = size_t(cx.i1 - cx.i), dy = sy * size_t(cy.i1 - cy.i),
                     dz = sz * size_t(cz.i1 - cz.i);
        const double c[8] = {p[0],  p[dx],      p[dy],      p[dy + dx],
                             p[dz], p[dz + dx], p[dz + dy], p[dz + dy + dx]};
        return trilinear(c, cx.t, cy.t, cz.t);
    }
};

struct Bricked {
    const BrickGrid<float>* g;
    float voxel(int x, int y, int z) const { return g->get(x, y, z); }
    double sample(double x, double y, double z) const { return g->sample(x, y, z); }
};

/// The bricked grid, prefetching the brick a few voxels ahead along the ray.
struct BrickedAhead : Bricked {
    mutable std::size_t last = ~std::size_t(0);
    void ahead(double x, double y, double z) const {
        const int ix = int(x), iy = int(y), iz = int(z);
        // prefetchBrick returns the brick number; a repeated hint costs only the key.
        const int mask = g->index().brickSide() - 1;
        if (((ix ^ lx) | (iy ^ ly) | (iz ^ lz)) & ~mask)
            last = g->prefetchBrick(ix, iy, iz), lx = ix, ly = iy, lz = iz;
    }
    mutable int lx = -100, ly = -100, lz = -100;
};

/// The flat array, prefetching the 4 lines of the stencil a few voxels ahead along the ray.
struct FlatAhead : Flat {
    void ahead(double x, double y, double z) const {
        const int ix = std::min(std::max(int(x), 0), n - 2),
                  iy = std::min(std::max(int(y), 0), n - 2),
                  iz = std::min(std::max(int(z), 0), n - 2);
        const float* p = d + size_t(ix) + size_t(n) * (size_t(iy) + size_t(n) * size_t(iz));
        const size_t sy = size_t(n), sz = size_t(n) * size_t(n);
        __builtin_prefetch(p);
        __builtin_prefetch(p + sy);
        __builtin_prefetch(p + sz);
        __builtin_prefetch(p + sz + sy);
    }
};

/// OpenVDB through a ValueAccessor (it caches the path to the last leaf), corners read one by
/// one with the same cell choice and formula as the others.
struct Vdb {
    openvdb::FloatGrid::ConstAccessor* acc;
    int n;
    float voxel(int x, int y, int z) const { return acc->getValue(openvdb::Coord(x, y, z)); }
    double sample(double x, double y, double z) const {
        const SampleCell cx = sampleCell(x, n), cy = sampleCell(y, n), cz = sampleCell(z, n);
        double c[8];
        for (int j = 0; j < 8; ++j)
            c[j] = acc->getValue(
                openvdb::Coord(j & 1 ? cx.i1 : cx.i, j & 2 ? cy.i1 : cy.i, j & 4 ? cz.i1 : cz.i));
        return trilinear(c, cx.t, cy.t, cz.t);
    }
};

/// OpenVDB's own trilinear sampler on the accessor (its stencil read and its formula).
struct VdbBoxSampler {
    openvdb::FloatGrid::ConstAccessor* acc;
    double sample(double x, double y, double z) const {
        return openvdb::tools::BoxSampler::sample(*acc, openvdb::Vec3R(x, y, z));
    }
};

// ---- the workloads ----

struct Line {
    double o[3], d[3];
    double t0;
    int count;
};

/// Lines through random points of the cube [0, N−1]³ along directions uniform on the sphere,
/// clipped to the cube: samples at t0 + k/2, k < count.
std::vector<Line> makeLines(int rays, int n) {
    std::mt19937_64 rng(2024);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double top = double(n - 1);
    std::vector<Line> lines;
    while (int(lines.size()) < rays) {
        Line l;
        const double z = 2.0 * u(rng) - 1.0, phi = 2.0 * M_PI * u(rng), r = std::sqrt(1.0 - z * z);
        l.d[0] = r * std::cos(phi);
        l.d[1] = r * std::sin(phi);
        l.d[2] = z;
        for (int a = 0; a < 3; ++a) l.o[a] = top * u(rng);
        double t0 = -1e300, t1 = 1e300;
        for (int a = 0; a < 3; ++a) {
            if (l.d[a] == 0.0) continue;
            double ta = (0.0 - l.o[a]) / l.d[a], tb = (top - l.o[a]) / l.d[a];
            if (ta > tb) std::swap(ta, tb);
            t0 = std::max(t0, ta);
            t1 = std::min(t1, tb);
        }
        l.t0 = t0;
        l.count = int(std::floor((t1 - t0) * 2.0)) + 1;
        lines.push_back(l);
    }
    return lines;
}

/// A volume renderer's rays: an orthographic view of the cube along a fixed oblique direction,
/// `pixels`² parallel rays one voxel apart through the cube's centre, in 8 × 8 pixel tiles, so
/// that neighbouring rays read neighbouring voxels (the coherence the literature's figures
/// rely on), clipped to the cube like makeLines'.
std::vector<Line> makeCameraLines(int pixels, int n) {
    const double top = double(n - 1), c = 0.5 * top;
    const double d[3] = {0.48, 0.36, 0.8};  // unit: 0.48² + 0.36² + 0.8² = 1
    // u ⟂ d in the x-y plane, v = d × u.
    const double ul = std::hypot(d[0], d[1]);
    const double u[3] = {-d[1] / ul, d[0] / ul, 0.0};
    const double v[3] = {d[1] * u[2] - d[2] * u[1], d[2] * u[0] - d[0] * u[2],
                         d[0] * u[1] - d[1] * u[0]};
    std::vector<Line> lines;
    for (int ty = 0; ty < pixels; ty += 8)
        for (int tx = 0; tx < pixels; tx += 8)
            for (int py = ty; py < std::min(pixels, ty + 8); ++py)
                for (int px = tx; px < std::min(pixels, tx + 8); ++px) {
                    const double a = px - 0.5 * pixels + 0.5, b = py - 0.5 * pixels + 0.5;
                    Line l;
                    for (int k = 0; k < 3; ++k) {
                        l.d[k] = d[k];
                        l.o[k] = c + a * u[k] + b * v[k];
                    }
                    double t0 = -1e300, t1 = 1e300;
                    for (int k = 0; k < 3; ++k) {
                        double ta = (0.0 - l.o[k]) / l.d[k], tb = (top - l.o[k]) / l.d[k];
                        if (ta > tb) std::swap(ta, tb);
                        t0 = std::max(t0, ta);
                        t1 = std::min(t1, tb);
                    }
                    if (!(t0 <= t1)) continue;
                    l.t0 = t0;
                    l.count = int(std::floor((t1 - t0) * 2.0)) + 1;
                    lines.push_back(l);
                }
    return lines;
}

/// The march with a hint ahead(point kAhead voxels further) before each sample.
template <class S>
double marchAhead(const S& s, const std::vector<Line>& lines, double kAhead) {
    double total = 0.0;
    for (const Line& l : lines) {
        double sum = 0.0;
        for (int k = 0; k < l.count; ++k) {
            const double t = l.t0 + 0.5 * k, ta = t + kAhead;
            s.ahead(l.o[0] + ta * l.d[0], l.o[1] + ta * l.d[1], l.o[2] + ta * l.d[2]);
            sum += s.sample(l.o[0] + t * l.d[0], l.o[1] + t * l.d[1], l.o[2] + t * l.d[2]);
        }
        total += sum;
    }
    return total;
}

template <class S>
double march(const S& s, const std::vector<Line>& lines) {
    double total = 0.0;
    for (const Line& l : lines) {
        double sum = 0.0;
        for (int k = 0; k < l.count; ++k) {
            const double t = l.t0 + 0.5 * k;
            sum += s.sample(l.o[0] + t * l.d[0], l.o[1] + t * l.d[1], l.o[2] + t * l.d[2]);
        }
        total += sum;
    }
    return total;
}

template <class S>
double points(const S& s, int count, int n) {
    Rng rng{77};
    double sum = 0.0;
    for (int k = 0; k < count; ++k) {
        const int x = rng.below(n), y = rng.below(n), z = rng.below(n);
        sum += s.voxel(x, y, z);
    }
    return sum;
}

template <class S>
double samples(const S& s, int count, int n) {
    Rng rng{78};
    const double top = double(n - 1);
    double sum = 0.0;
    for (int k = 0; k < count; ++k) {
        const double x = top * rng.unit(), y = top * rng.unit(), z = top * rng.unit();
        sum += s.sample(x, y, z);
    }
    return sum;
}

/// Every voxel of `count` planes normal to `axis`, the inner loop along the lower remaining
/// axis (the flat array's faster one).
template <class S>
double slices(const S& s, int axis, int count, int n) {
    double sum = 0.0;
    for (int k = 0; k < count; ++k) {
        const int c = int((std::int64_t(2 * k + 1) * n) / (2 * count));
        for (int b = 0; b < n; ++b)
            for (int a = 0; a < n; ++a) {
                switch (axis) {
                    case 0: sum += s.voxel(c, a, b); break;
                    case 1: sum += s.voxel(a, c, b); break;
                    default: sum += s.voxel(a, b, c); break;
                }
            }
    }
    return sum;
}

/// One workload on every storage: its timings (cpu, wall per run) and its sums.
struct Row {
    std::string name;
    double units = 0;  ///< reads or samples per run, for ns per unit
    std::vector<std::string> storages;
    std::vector<std::function<double()>> run;
    std::vector<std::vector<double>> cpu, wall;
    std::vector<double> sum;
};

void parse(int argc, char** argv, Options& o) {
    for (int i = 1; i < argc; ++i) {
        auto value = [&](const char* name) {
            if (i + 1 >= argc) {
                std::fprintf(stderr, "kerf_brick_bench: %s needs a value\n", name);
                std::exit(2);
            }
            char* end = nullptr;
            const long v = std::strtol(argv[++i], &end, 10);
            if (*end || v < 0 || v > 1000000000) {
                std::fprintf(stderr, "kerf_brick_bench: %s %s is not a count\n", name, argv[i]);
                std::exit(2);
            }
            return int(v);
        };
        const std::string a = argv[i];
        if (a == "--size")
            o.size = value("--size");
        else if (a == "--runs")
            o.runs = value("--runs");
        else if (a == "--rays")
            o.rays = value("--rays");
        else if (a == "--points")
            o.points = value("--points");
        else if (a == "--slices")
            o.slices = value("--slices");
        else if (a == "--brick")
            o.layout.brickLog2 = value("--brick");
        else if (a == "--macro")
            o.layout.macroLog2 = value("--macro");
        else if (a == "--only" && i + 1 < argc)
            o.only = argv[++i];
        else if (a == "--ahead-flat")
            o.aheadFlat = value("--ahead-flat");
        else if (a == "--ahead-brick")
            o.aheadBrick = value("--ahead-brick");
        else if (a == "--camera")
            o.cameraPixels = value("--camera");
        else {
            std::fprintf(stderr, "kerf_brick_bench: unknown argument %s\n", a.c_str());
            std::exit(2);
        }
    }
    if (o.size < 2 || o.size > 2048 || o.runs < 1 || o.slices < 1 || o.slices > o.size) {
        std::fprintf(stderr,
                     "kerf_brick_bench: --size in [2, 2048], --runs ≥ 1, --slices in [1, size]\n");
        std::exit(2);
    }
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    parse(argc, argv, o);
    const int n = o.size;
    openvdb::initialize();

    // The field: separable sine tables, so filling 512³ voxels costs a few products each.
    constexpr int kTerms = 6;
    std::vector<double> tab[kTerms][3];
    double amp[kTerms];
    {
        std::mt19937_64 rng(7);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        for (int k = 0; k < kTerms; ++k) {
            amp[k] = 1.0 / (k + 1);
            for (int a = 0; a < 3; ++a) {
                const double w = (0.02 + 0.25 * u(rng)) * (k + 1) * 0.5,
                             phase = 2.0 * M_PI * u(rng);
                tab[k][a].resize(size_t(n));
                for (int i = 0; i < n; ++i) tab[k][a][size_t(i)] = std::sin(w * i + phase);
            }
        }
    }
    auto field = [&](int x, int y, int z) {
        double v = 0.0;
        for (int k = 0; k < kTerms; ++k)
            v += amp[k] * tab[k][0][size_t(x)] * tab[k][1][size_t(y)] * tab[k][2][size_t(z)];
        return float(v);
    };

    const double mib = double(n) * n * n * 4.0 / (1 << 20);
    std::printf(
        "Field: %d³ floats (%.0f MiB per copy); bricks of %d³ voxels in macrobricks of %d³ "
        "bricks\n",
        n, mib, 1 << o.layout.brickLog2, 1 << o.layout.macroLog2);
    auto t0 = std::chrono::steady_clock::now();
    std::vector<float> flatData(size_t(n) * n * n);
    tbb::parallel_for(0, n, [&](int z) {
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x)
                flatData[size_t(x) + size_t(n) * (size_t(y) + size_t(n) * z)] = field(x, y, z);
    });
    BrickGrid<float> grid({n, n, n}, 0.0f, o.layout);
    grid.fill([&](int x, int y, int z) {
        return flatData[size_t(x) + size_t(n) * (size_t(y) + size_t(n) * z)];
    });
    openvdb::FloatGrid::Ptr vdb = openvdb::FloatGrid::create(0.0f);
    {
        openvdb::tools::Dense<float, openvdb::tools::LayoutXYZ> dense(
            openvdb::CoordBBox(openvdb::Coord(0), openvdb::Coord(n - 1)), flatData.data());
        openvdb::tools::copyFromDense(dense, vdb->tree(), 0.0f);
    }
    const double built =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    // The copies must hold the same floats: checked on every voxel once.
    long mismatches = 0;
    {
        openvdb::FloatGrid::ConstAccessor acc = vdb->getConstAccessor();
        for (int z = 0; z < n; ++z)
            for (int y = 0; y < n; ++y)
                for (int x = 0; x < n; ++x) {
                    const float f = flatData[size_t(x) + size_t(n) * (size_t(y) + size_t(n) * z)];
                    mismatches +=
                        grid.get(x, y, z) != f || acc.getValue(openvdb::Coord(x, y, z)) != f;
                }
    }
    std::printf(
        "Built in %.1f s; voxels differing between the copies: %ld; memory: flat %.0f MiB, "
        "bricked %.0f MiB, OpenVDB %.0f MiB\n\n",
        built, mismatches, mib, double(grid.voxelBytes()) / (1 << 20),
        double(vdb->memUsage()) / (1 << 20));

    openvdb::FloatGrid::ConstAccessor accessor = vdb->getConstAccessor();
    const Flat flat{flatData.data(), n};
    const Bricked bricked{&grid};
    const Vdb vdbAcc{&accessor, n};
    const VdbBoxSampler vdbBox{&accessor};
    const std::vector<Line> lines = makeLines(o.rays, n);
    double marchSamples = 0;
    for (const Line& l : lines) marchSamples += l.count;

    std::vector<Row> rows;
    auto add = [&](const std::string& name, double units, auto fFlat, auto fBrick, auto fVdb) {
        Row r;
        r.name = name;
        r.units = units;
        r.storages = {"flat", "bricked", "OpenVDB"};
        r.run = {fFlat, fBrick, fVdb};
        rows.push_back(r);
    };
    add(
        "march", marchSamples, [&] { return march(flat, lines); },
        [&] { return march(bricked, lines); }, [&] { return march(vdbAcc, lines); });
    rows.back().storages.push_back("OpenVDB BoxSampler");
    rows.back().run.push_back([&] { return march(vdbBox, lines); });
    const FlatAhead flatAhead{flat};
    const BrickedAhead brickedAhead{bricked};
    add(
        "march, prefetch ahead", marchSamples,
        [&] { return marchAhead(flatAhead, lines, o.aheadFlat); },
        [&] { return marchAhead(brickedAhead, lines, o.aheadBrick); },
        [&] { return march(vdbAcc, lines); });
    const std::vector<Line> camera = makeCameraLines(o.cameraPixels, n);
    double cameraSamples = 0;
    for (const Line& l : camera) cameraSamples += l.count;
    add(
        "march, camera", cameraSamples, [&] { return march(flat, camera); },
        [&] { return march(bricked, camera); }, [&] { return march(vdbAcc, camera); });
    add(
        "march, camera, prefetch ahead", cameraSamples,
        [&] { return marchAhead(flatAhead, camera, o.aheadFlat); },
        [&] { return marchAhead(brickedAhead, camera, o.aheadBrick); },
        [&] { return march(vdbAcc, camera); });
    add(
        "points", o.points, [&] { return points(flat, o.points, n); },
        [&] { return points(bricked, o.points, n); }, [&] { return points(vdbAcc, o.points, n); });
    add(
        "samples", o.points, [&] { return samples(flat, o.points, n); },
        [&] { return samples(bricked, o.points, n); },
        [&] { return samples(vdbAcc, o.points, n); });
    const double sliceUnits = double(o.slices) * n * n;
    const char* axes[3] = {"slice x", "slice y", "slice z"};
    for (int a = 0; a < 3; ++a)
        add(
            axes[a], sliceUnits, [&, a] { return slices(flat, a, o.slices, n); },
            [&, a] { return slices(bricked, a, o.slices, n); },
            [&, a] { return slices(vdbAcc, a, o.slices, n); });

    rows.erase(
        std::remove_if(rows.begin(), rows.end(),
                       [&](const Row& r) { return r.name.compare(0, o.only.size(), o.only) != 0; }),
        rows.end());
    for (Row& r : rows) {
        r.cpu.assign(r.run.size(), {});
        r.wall.assign(r.run.size(), {});
        r.sum.assign(r.run.size(), 0.0);
    }
    for (int run = 0; run < o.runs; ++run)
        for (Row& r : rows)
            for (size_t s = 0; s < r.run.size(); ++s) {
                const auto w0 = std::chrono::steady_clock::now();
                const double c0 = thread_seconds();
                const double v = r.run[s]();
                r.cpu[s].push_back(thread_seconds() - c0);
                r.wall[s].push_back(
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count());
                if (run > 0 && v != r.sum[s] && !(std::isnan(v) && std::isnan(r.sum[s]))) {
                    std::fprintf(stderr, "kerf_brick_bench: %s on %s gave two sums\n",
                                 r.name.c_str(), r.storages[s].c_str());
                    return 1;
                }
                r.sum[s] = v;
            }

    std::printf(
        "| workload | reads or samples | storage | ns each (CPU) | ns each (wall) | speed-up over "
        "flat (CPU) | sum | sum − flat's |\n");
    std::printf("|---|---:|---|---:|---:|---:|---:|---:|\n");
    for (const Row& r : rows) {
        const double flatCpu = median(r.cpu[0]);
        for (size_t s = 0; s < r.run.size(); ++s) {
            const double c = median(r.cpu[s]), w = median(r.wall[s]);
            std::printf("| %s | %.3g | %s | %.2f | %.2f | %.2f× | %.10g | %.3g |\n", r.name.c_str(),
                        r.units, r.storages[s].c_str(), 1e9 * c / r.units, 1e9 * w / r.units,
                        flatCpu / c, r.sum[s], r.sum[s] - r.sum[0]);
        }
    }
    std::printf("\nMedian of %d runs; the storages alternate within each run.\n", o.runs);
    return 0;
}
