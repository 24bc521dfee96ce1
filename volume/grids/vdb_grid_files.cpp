// .vdb files from plain values, and float grids read back (volume/grids/vdb_grid_files.h).
#include "volume/grids/vdb_grid_files.h"

#include <openvdb/openvdb.h>
#include <openvdb/tools/Interpolation.h>
#include <openvdb/tools/SignedFloodFill.h>

#include <stdexcept>

namespace kerf {

struct VdbFloatGrid::Impl {
    openvdb::FloatGrid::ConstPtr grid;
};

namespace {

template <class GridT>
void place(GridT& grid, const VdbGridToWrite& in) {
    auto transform = openvdb::math::Transform::createLinearTransform(in.voxel);
    if (in.turnZ != 0.0) transform->postRotate(in.turnZ, openvdb::math::Z_AXIS);
    if (in.move != Vec3(0.0))
        transform->postTranslate(openvdb::Vec3d(in.move.x, in.move.y, in.move.z));
    grid.setTransform(transform);
    grid.setName(in.name);
    grid.setSaveFloatAsHalf(in.saveAsHalf);
}

openvdb::GridBase::Ptr makeGrid(const VdbGridToWrite& in) {
    if (in.kind == VdbGridToWrite::Kind::Vec3) {
        auto grid = openvdb::Vec3SGrid::create(openvdb::Vec3s(in.background));
        place(*grid, in);
        for (const auto& [c, v] : in.values)
            grid->tree().setValue(openvdb::Coord(c[0], c[1], c[2]), openvdb::Vec3s(v));
        return grid;
    }
    auto grid = openvdb::FloatGrid::create(in.background);
    place(*grid, in);
    grid->setGridClass(in.kind == VdbGridToWrite::Kind::LevelSet    ? openvdb::GRID_LEVEL_SET
                       : in.kind == VdbGridToWrite::Kind::FogVolume ? openvdb::GRID_FOG_VOLUME
                                                                    : openvdb::GRID_UNKNOWN);
    auto acc = grid->getAccessor();
    for (const auto& [c, v] : in.values) acc.setValue(openvdb::Coord(c[0], c[1], c[2]), v);
    if (in.fillSigns) openvdb::tools::signedFloodFill(grid->tree());
    return grid;
}

}  // namespace

void writeVdbGrids(const std::string& path, const std::vector<VdbGridToWrite>& grids,
                   const VdbCompression& compression) {
    openvdb::initialize();
    openvdb::GridPtrVec out;
    for (const VdbGridToWrite& g : grids) out.push_back(makeGrid(g));
    try {
        openvdb::io::File file(path);
        using Codec = VdbCompression::Codec;
        file.setCompression((compression.codec == Codec::Blosc ? openvdb::io::COMPRESS_BLOSC
                             : compression.codec == Codec::Zip ? openvdb::io::COMPRESS_ZIP
                                                               : openvdb::io::COMPRESS_NONE) |
                            (compression.activeMask ? openvdb::io::COMPRESS_ACTIVE_MASK
                                                    : openvdb::io::COMPRESS_NONE));
        file.write(out);
        file.close();
    } catch (const openvdb::Exception& e) {
        throw std::runtime_error("cannot write '" + path + "': " + e.what());
    }
}

std::vector<VdbFloatGrid> readVdbFloatGrids(const std::string& path) {
    openvdb::initialize();
    openvdb::GridPtrVecPtr grids;
    try {
        openvdb::io::File file(path);
        file.open();
        grids = file.getGrids();
        file.close();
    } catch (const openvdb::Exception& e) {
        throw std::runtime_error("cannot read '" + path + "': " + e.what());
    }
    std::vector<VdbFloatGrid> out;
    for (const openvdb::GridBase::Ptr& base : *grids) {
        auto grid = openvdb::GridBase::grid<openvdb::FloatGrid>(base);
        if (!grid) continue;
        VdbFloatGrid g;
        g.name = grid->getName();
        g.gridClass = grid->getGridClass() == openvdb::GRID_LEVEL_SET    ? "level set"
                      : grid->getGridClass() == openvdb::GRID_FOG_VOLUME ? "fog volume"
                                                                         : "unknown";
        g.linear = grid->transform().isLinear();
        const openvdb::Vec3d size = grid->voxelSize(),
                             at = grid->transform().indexToWorld(openvdb::Vec3d(0.0));
        g.voxelSize = Vec3(size.x(), size.y(), size.z());
        g.origin = Vec3(at.x(), at.y(), at.z());
        g.background = grid->background();
        g.impl = std::make_shared<const VdbFloatGrid::Impl>(VdbFloatGrid::Impl{grid});
        out.push_back(std::move(g));
    }
    return out;
}

float VdbFloatGrid::value(int i, int j, int k) const {
    return impl->grid->tree().getValue(openvdb::Coord(i, j, k));
}

bool VdbFloatGrid::active(int i, int j, int k) const {
    return impl->grid->tree().isValueOn(openvdb::Coord(i, j, k));
}

uint64_t VdbFloatGrid::activeVoxelCount() const { return impl->grid->activeVoxelCount(); }

void VdbFloatGrid::forEachActive(const std::function<void(int, int, int, float)>& visit) const {
    for (auto it = impl->grid->cbeginValueOn(); it; ++it) {
        if (!it.isVoxelValue()) {  // an active tile: each of its voxels
            openvdb::CoordBBox box;
            it.getBoundingBox(box);
            for (auto c = box.begin(); c; ++c) visit((*c).x(), (*c).y(), (*c).z(), *it);
            continue;
        }
        const openvdb::Coord c = it.getCoord();
        visit(c.x(), c.y(), c.z(), *it);
    }
}

double VdbFloatGrid::sampleWorld(const Vec3& p) const {
    const openvdb::tools::GridSampler<openvdb::FloatGrid, openvdb::tools::BoxSampler> sampler(
        *impl->grid);
    return sampler.wsSample(openvdb::Vec3d(p.x, p.y, p.z));
}

}  // namespace kerf
