// kerf's level-set solid (volume/grids/level_set_node.h) against OpenVDB's LevelSetRayIntersector
// on the same grids and the same rays, one thread, same run (issue 14 §3; docs/BENCHMARKS.md,
// "Level sets against OpenVDB"). A sphere level set of 517³ voxels and a torus, written with
// OpenVDB and read back by kerf's loader; a pinhole camera's primary rays; hit position and
// normal from both. Reports rays/s (median of the runs), the depth error in voxels against the
// analytic sphere (mean and max over the pixels both hit), and on the torus the pixels where
// the torus shrunk by one voxel is hit (kerf's closed-form torus) but the level set is missed.
//
//   kerf_vdb_ray_bench [--out DIR] [--size N] [--runs R] [--radius-voxels V]
#include "csg/tree/solids.h"
#include "volume/grids/level_set_node.h"
#include "volume/grids/vdb_level_set.h"

#include <openvdb/openvdb.h>
#include <openvdb/tools/LevelSetSphere.h>
#include <openvdb/tools/RayIntersector.h>
#include <openvdb/tools/SignedFloodFill.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

using namespace kerf;

namespace {

struct Options {
    std::string out = "bench/out/vdb";
    int size = 512;  // image side in pixels
    int runs = 5;
    int radiusVoxels = 256;  // 256 voxels + a 3-voxel band: active voxels span 517³
};

struct Pixel {
    bool hit = false;
    double t = 0.0;
};

/// The camera's rays: from `eye` towards `target`, a field of view that frames a box of
/// half-size `half` at the target.
std::vector<Ray> cameraRays(const Vec3& eye, const Vec3& target, double half, int size) {
    const Vec3 w = glm::normalize(target - eye);
    const Vec3 u = glm::normalize(glm::cross(w, Vec3(0, 1, 0.1)));
    const Vec3 v = glm::cross(u, w);
    const double scale = 1.15 * half / glm::length(target - eye);
    std::vector<Ray> rays;
    rays.reserve(size_t(size) * size);
    for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i) {
            const double x = (2 * (i + 0.5) / size - 1) * scale,
                         y = (2 * (j + 0.5) / size - 1) * scale;
            rays.push_back({eye, glm::normalize(w + x * u + y * v)});
        }
    return rays;
}

double seconds(std::chrono::steady_clock::time_point a) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - a).count();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

/// Traces every ray with kerf's solid; returns the seconds taken.
double traceKerf(const NodePtr& solid, const std::vector<Ray>& rays, std::vector<Pixel>& px) {
    px.assign(rays.size(), {});
    TraceContext ctx;
    const auto start = std::chrono::steady_clock::now();
    for (size_t i = 0; i < rays.size(); ++i) {
        Boundary hit;
        bool entering;
        if (solid->firstSurface(rays[i], 0.0, kInf, ctx, hit, entering)) px[i] = {true, hit.t};
    }
    return seconds(start);
}

/// The same with OpenVDB's LevelSetRayIntersector (world position and normal, as kerf gives).
double traceVdb(const openvdb::FloatGrid& grid, const std::vector<Ray>& rays,
                std::vector<Pixel>& px) {
    px.assign(rays.size(), {});
    openvdb::tools::LevelSetRayIntersector<openvdb::FloatGrid> lsri(grid);
    const auto start = std::chrono::steady_clock::now();
    for (size_t i = 0; i < rays.size(); ++i) {
        const Ray& r = rays[i];
        const openvdb::math::Ray<double> ray(openvdb::Vec3d(r.origin.x, r.origin.y, r.origin.z),
                                             openvdb::Vec3d(r.dir.x, r.dir.y, r.dir.z));
        openvdb::Vec3d world, normal;
        if (lsri.intersectsWS(ray, world, normal))
            px[i] = {true, (world - ray.eye()).dot(ray.dir())};  // unit direction: t = distance
    }
    return seconds(start);
}

openvdb::FloatGrid::Ptr torusGrid(double R, double r, double voxel) {
    const float band = float(3 * voxel);
    auto grid = openvdb::FloatGrid::create(band);
    grid->setTransform(openvdb::math::Transform::createLinearTransform(voxel));
    grid->setGridClass(openvdb::GRID_LEVEL_SET);
    grid->setName("torus");
    auto acc = grid->getAccessor();
    const int n = int(std::ceil((R + r) / voxel)) + 4, m = int(std::ceil(r / voxel)) + 4;
    for (int i = -n; i <= n; ++i)
        for (int k = -n; k <= n; ++k) {
            const double q0 = std::sqrt(double(i) * i + double(k) * k) * voxel - R;
            if (std::fabs(q0) > r + 4 * voxel) continue;
            for (int j = -m; j <= m; ++j) {
                const double d = std::sqrt(q0 * q0 + (j * voxel) * (j * voxel)) - r;
                if (std::fabs(d) < band) acc.setValue(openvdb::Coord(i, j, k), float(d));
            }
        }
    openvdb::tools::signedFloodFill(grid->tree());
    return grid;
}

struct Result {
    double kerfRate, vdbRate;
    int kerfHits = 0, vdbHits = 0;
    int kerfOnly = 0, vdbOnly = 0;  ///< pixels one method hits and the other misses
};

/// Runs both tracers `runs` times, alternating; the median rays/s of each.
Result race(const NodePtr& solid, const openvdb::FloatGrid& grid, const std::vector<Ray>& rays,
            int runs, std::vector<Pixel>& kerfPx, std::vector<Pixel>& vdbPx) {
    std::vector<double> k, v;
    for (int i = 0; i < runs; ++i) {
        k.push_back(rays.size() / traceKerf(solid, rays, kerfPx));
        v.push_back(rays.size() / traceVdb(grid, rays, vdbPx));
    }
    Result r{median(k), median(v)};
    for (size_t i = 0; i < rays.size(); ++i) {
        r.kerfHits += kerfPx[i].hit, r.vdbHits += vdbPx[i].hit;
        r.kerfOnly += kerfPx[i].hit && !vdbPx[i].hit, r.vdbOnly += vdbPx[i].hit && !kerfPx[i].hit;
    }
    return r;
}

/// The analytic ray–sphere entry in long double.
bool sphereT(const Ray& ray, double radius, long double& t) {
    const long double ox = ray.origin.x, oy = ray.origin.y, oz = ray.origin.z;
    const long double dx = ray.dir.x, dy = ray.dir.y, dz = ray.dir.z;
    const long double a = dx * dx + dy * dy + dz * dz, b = ox * dx + oy * dy + oz * dz;
    const long double c = ox * ox + oy * oy + oz * oz - (long double)radius * radius;
    const long double disc = b * b - a * c;
    if (disc < 0) return false;
    t = (-b - std::sqrt(disc)) / a;
    return true;
}

void depthErrors(const std::vector<Ray>& rays, const std::vector<Pixel>& px, double radius,
                 double voxel, double& mean, double& worst, int& missed, int& shrunkHits) {
    double sum = 0.0;
    int n = 0;
    worst = 0.0;
    missed = shrunkHits = 0;
    for (size_t i = 0; i < rays.size(); ++i) {
        long double t;
        if (sphereT(rays[i], radius - voxel, t)) {
            ++shrunkHits;
            if (!px[i].hit) ++missed;
        }
        if (!px[i].hit || !sphereT(rays[i], radius, t)) continue;
        const double e = double(std::fabs((long double)px[i].t - t)) / voxel;  // |dir| = 1
        sum += e;
        worst = std::max(worst, e);
        ++n;
    }
    mean = n ? sum / n : 0.0;
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string a = argv[i];
        if (a == "--out")
            o.out = argv[i + 1];
        else if (a == "--size")
            o.size = std::atoi(argv[i + 1]);
        else if (a == "--runs")
            o.runs = std::atoi(argv[i + 1]);
        else if (a == "--radius-voxels")
            o.radiusVoxels = std::atoi(argv[i + 1]);
        else {
            std::fprintf(stderr, "kerf_vdb_ray_bench: unknown option %s\n", a.c_str());
            return 2;
        }
    }
    openvdb::initialize();
    std::filesystem::create_directories(o.out);
    const double radius = 1.0, voxel = radius / o.radiusVoxels;

    // The sphere.
    const std::string spherePath = o.out + "/sphere.vdb";
    {
        auto g = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(
            float(radius), openvdb::Vec3f(0.f), float(voxel), 3.f);
        g->setName("sphere");
        openvdb::io::File(spherePath).write({g});
    }
    openvdb::io::File file(spherePath);
    file.open(false);  // read whole now, as kerf does: no leaf loaded during the timed runs
    const auto sphere = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid("sphere"));
    file.close();
    const auto start = std::chrono::steady_clock::now();
    const auto kerfSphere = loadLevelSet(spherePath);
    const double loadSeconds = seconds(start);
    const openvdb::CoordBBox box = sphere->evalActiveVoxelBoundingBox();
    std::printf(
        "sphere: %d³ active voxels (%llu), OpenVDB %.1f MiB in memory (%.1f MiB file); kerf: load "
        "%.2f s, %.1f MiB\n",
        box.dim().x(), (unsigned long long)sphere->activeVoxelCount(),
        sphere->memUsage() / 1048576.0, std::filesystem::file_size(spherePath) / 1048576.0,
        loadSeconds, kerfSphere->memoryBytes() / 1048576.0);
    const std::vector<Ray> sphereRays = cameraRays(Vec3(0.3, 0.4, 3.0), Vec3(0.0), radius, o.size);
    std::vector<Pixel> kp, vp;
    const Result s = race(levelSetSolid(kerfSphere), *sphere, sphereRays, o.runs, kp, vp);
    double kMean, kMax, vMean, vMax;
    int kMissed, vMissed, shrunk;
    depthErrors(sphereRays, kp, radius, voxel, kMean, kMax, kMissed, shrunk);
    depthErrors(sphereRays, vp, radius, voxel, vMean, vMax, vMissed, shrunk);

    // The torus (around y), seen at an angle so its silhouette has grazing rays: at the sphere's
    // voxel size, and coarse (the tube 4 voxels in radius), where grazing rays cross only a sliver.
    const double R = 0.7, r = 0.3;
    struct TorusResult {
        std::string label;
        Result race;
        int shrunk = 0, kerfMissed = 0, vdbMissed = 0;
    };
    std::vector<TorusResult> tori;
    for (const double h : {voxel, r / 4}) {
        const std::string torusPath = o.out + "/torus.vdb";
        const auto torus = torusGrid(R, r, h);
        openvdb::io::File(torusPath).write({torus});
        const auto kerfTorus = loadLevelSet(torusPath);
        const std::vector<Ray> torusRays =
            cameraRays(Vec3(0.5, 1.6, 2.6), Vec3(0.0), R + r, o.size);
        std::vector<Pixel> kt, vt;
        TorusResult tr;
        const openvdb::CoordBBox tb = torus->evalActiveVoxelBoundingBox();
        tr.label = "torus " + std::to_string(tb.dim().x()) + "×" + std::to_string(tb.dim().y()) +
                   "×" + std::to_string(tb.dim().z());
        tr.race = race(levelSetSolid(kerfTorus), *torus, torusRays, o.runs, kt, vt);
        const NodePtr shrunkTorus = makeTorus(R, r - h);
        TraceContext ctx;
        for (size_t i = 0; i < torusRays.size(); ++i) {
            Boundary hit;
            bool entering;
            if (!shrunkTorus->firstSurface(torusRays[i], 0.0, kInf, ctx, hit, entering)) continue;
            ++tr.shrunk;
            tr.kerfMissed += !kt[i].hit;
            tr.vdbMissed += !vt[i].hit;
        }
        tori.push_back(tr);
    }

    std::printf("\n%d×%d rays, one thread, median of %d runs\n\n", o.size, o.size, o.runs);
    std::printf(
        "| grid | method | rays/s | hits | hits the other misses | mean depth error (voxel) | max "
        "depth error (voxel) | missed (shrunk surface hit) |\n");
    std::printf("|---|---|---:|---:|---:|---:|---:|---:|\n");
    std::printf("| sphere %d³ | kerf volume | %.3g M | %d | %d | %.5f | %.4f | %d of %d |\n",
                box.dim().x(), s.kerfRate / 1e6, s.kerfHits, s.kerfOnly, kMean, kMax, kMissed,
                shrunk);
    std::printf(
        "| sphere %d³ | LevelSetRayIntersector | %.3g M | %d | %d | %.5f | %.4f | %d of %d |\n",
        box.dim().x(), s.vdbRate / 1e6, s.vdbHits, s.vdbOnly, vMean, vMax, vMissed, shrunk);
    for (const TorusResult& tr : tori) {
        std::printf("| %s | kerf volume | %.3g M | %d | %d | | | %d of %d |\n", tr.label.c_str(),
                    tr.race.kerfRate / 1e6, tr.race.kerfHits, tr.race.kerfOnly, tr.kerfMissed,
                    tr.shrunk);
        std::printf("| %s | LevelSetRayIntersector | %.3g M | %d | %d | | | %d of %d |\n",
                    tr.label.c_str(), tr.race.vdbRate / 1e6, tr.race.vdbHits, tr.race.vdbOnly,
                    tr.vdbMissed, tr.shrunk);
    }
    std::printf("\nkerf / OpenVDB speed: sphere %.2f×", s.kerfRate / s.vdbRate);
    for (const TorusResult& tr : tori)
        std::printf(", %s %.2f×", tr.label.c_str(), tr.race.kerfRate / tr.race.vdbRate);
    std::printf("\n");
    return 0;
}
