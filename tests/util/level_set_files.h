/// @file tests/util/level_set_files.h
/// @brief .vdb files for the level-set tests, written through volume/grids/vdb_grid_files.h: a
/// sphere and a torus around y (exact distances in a band of 3 voxels, the rest signed by OpenVDB's
/// flood fill), a fog volume and a vec3 grid (for the error messages).
#pragma once

#include "volume/grids/vdb_grid_files.h"

#include <cmath>
#include <functional>
#include <string>

namespace kerf::test {

using Grid = VdbGridToWrite;

inline void writeGrids(const std::string& path, const std::vector<Grid>& grids,
                       const VdbCompression& compression = {}) {
    writeVdbGrids(path, grids, compression);
}

/// A level set of the signed distance `sdf` (world units) over the index box ±n, half-width 3
/// voxels.
inline Grid distanceGrid(const std::function<double(double, double, double)>& sdf,
                         const std::array<int, 3>& n, double voxel, const std::string& name) {
    Grid g;
    g.name = name;
    g.voxel = voxel;
    g.background = float(3 * voxel);
    g.fillSigns = true;
    for (int i = -n[0]; i <= n[0]; ++i)
        for (int j = -n[1]; j <= n[1]; ++j)
            for (int k = -n[2]; k <= n[2]; ++k) {
                const double d = sdf(i * voxel, j * voxel, k * voxel);
                if (std::fabs(d) < 3 * voxel) g.values.push_back({{i, j, k}, float(d)});
            }
    return g;
}

/// A sphere level set of `radius` at `center` (world units).
inline Grid sphereGrid(double radius, const Vec3& center, double voxel,
                       const std::string& name = "sphere") {
    const int n = int(std::ceil((glm::length(center) + radius) / voxel)) + 4;
    return distanceGrid(
        [&](double x, double y, double z) { return glm::length(Vec3(x, y, z) - center) - radius; },
        {n, n, n}, voxel, name);
}

/// The signed distance to the torus (√(x² + z²) − R)² + y² = r², as kerf's makeTorus.
inline double torusDistance(double R, double r, double x, double y, double z) {
    const double q = std::sqrt(x * x + z * z) - R;
    return std::sqrt(q * q + y * y) - r;
}

/// A torus level set around y.
inline Grid torusGrid(double R, double r, double voxel, const std::string& name = "torus") {
    const int n = int(std::ceil((R + r) / voxel)) + 4, m = int(std::ceil(r / voxel)) + 4;
    return distanceGrid([&](double x, double y, double z) { return torusDistance(R, r, x, y, z); },
                        {n, m, n}, voxel, name);
}

/// A fog volume: densities in [0, 1] in a small cube.
inline Grid fogGrid(const std::string& name = "density") {
    Grid g;
    g.kind = Grid::Kind::FogVolume;
    g.name = name;
    for (int i = 0; i < 10; ++i)
        for (int j = 0; j < 10; ++j)
            for (int k = 0; k < 10; ++k) g.values.push_back({{i, j, k}, 0.1f * float(i + 1)});
    return g;
}

/// A vec3 grid (velocities).
inline Grid vectorGrid(const std::string& name = "vel") {
    Grid g;
    g.kind = Grid::Kind::Vec3;
    g.name = name;
    g.values.push_back({{1, 2, 3}, 1.0f});
    return g;
}

}  // namespace kerf::test
