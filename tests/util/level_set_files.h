/// @file tests/util/level_set_files.h
/// @brief .vdb files for the level-set tests, written with OpenVDB itself: a sphere
/// (createLevelSetSphere), a torus around y (exact distances in a narrow band, then
/// signedFloodFill), a fog volume and a vec3 grid (for the error messages).
#pragma once

#include <openvdb/openvdb.h>
#include <openvdb/tools/LevelSetSphere.h>
#include <openvdb/tools/SignedFloodFill.h>

#include <cmath>
#include <string>

namespace kerf::test {

inline void initVdb() { openvdb::initialize(); }

inline void writeGrids(const std::string& path, openvdb::GridPtrVec grids) {
    openvdb::io::File(path).write(grids);
}

/// A sphere level set of `radius` at `center` (world units), half-width 3 voxels.
inline openvdb::FloatGrid::Ptr sphereGrid(double radius, const openvdb::Vec3f& center, double voxel,
                                          const std::string& name = "sphere") {
    initVdb();
    auto grid = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(float(radius), center,
                                                                         float(voxel), 3.f);
    grid->setName(name);
    return grid;
}

/// The signed distance to the torus (√(x² + z²) − R)² + y² = r², as kerf's makeTorus.
inline double torusDistance(double R, double r, double x, double y, double z) {
    const double q = std::sqrt(x * x + z * z) - R;
    return std::sqrt(q * q + y * y) - r;
}

/// A torus level set: exact distances at the voxel centres within 3 voxels of the surface,
/// the inside and outside filled by sign.
inline openvdb::FloatGrid::Ptr torusGrid(double R, double r, double voxel, const std::string& name = "torus") {
    initVdb();
    const float band = float(3 * voxel);
    auto grid = openvdb::FloatGrid::create(band);
    grid->setTransform(openvdb::math::Transform::createLinearTransform(voxel));
    grid->setGridClass(openvdb::GRID_LEVEL_SET);
    grid->setName(name);
    auto acc = grid->getAccessor();
    const int n = int(std::ceil((R + r) / voxel)) + 4, m = int(std::ceil(r / voxel)) + 4;
    for (int i = -n; i <= n; ++i)
        for (int j = -m; j <= m; ++j)
            for (int k = -n; k <= n; ++k) {
                const double d = torusDistance(R, r, i * voxel, j * voxel, k * voxel);
                if (std::fabs(d) < band) acc.setValue(openvdb::Coord(i, j, k), float(d));
            }
    openvdb::tools::signedFloodFill(grid->tree());
    return grid;
}

/// A fog volume: densities in [0, 1] in a small cube.
inline openvdb::FloatGrid::Ptr fogGrid(const std::string& name = "density") {
    initVdb();
    auto grid = openvdb::FloatGrid::create(0.f);
    grid->setGridClass(openvdb::GRID_FOG_VOLUME);
    grid->setName(name);
    auto acc = grid->getAccessor();
    for (int i = 0; i < 10; ++i)
        for (int j = 0; j < 10; ++j)
            for (int k = 0; k < 10; ++k) acc.setValue(openvdb::Coord(i, j, k), 0.1f * float(i + 1));
    return grid;
}

/// A vec3 grid (velocities).
inline openvdb::Vec3SGrid::Ptr vectorGrid(const std::string& name = "vel") {
    initVdb();
    auto grid = openvdb::Vec3SGrid::create(openvdb::Vec3s(0.f));
    grid->setName(name);
    grid->tree().setValue(openvdb::Coord(1, 2, 3), openvdb::Vec3s(1.f, 0.f, 0.f));
    return grid;
}

}  // namespace kerf::test
