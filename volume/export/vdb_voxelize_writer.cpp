// The OpenVDB side of `kerf voxelize`: the narrow band of a closed mesh grown voxel by voxel
// from the voxels nearest its vertices, each voxel holding its exact distance to the mesh
// (volume/export/voxelize_distance.h) with the implicit's sign; the other voxels of its leaves
// ±band by the implicit's sign, the tiles by OpenVDB's signed flood fill; the grids serialised into
// the bytes of one .vdb file (written by the caller through io/atomic_file.h).
//
// OpenVDB's mesh-to-volume was tried first and left: it finds the outer layers of the band from
// the triangles of neighbouring voxels, which overestimated distances by up to 0.49 voxel on a
// sphere, and it left out a band layer on the inner side of a hollow sphere's wall.
#include "volume/export/vdb_voxelize_writer.h"

#include "csg/interval/interval.h"
#include "volume/export/voxelize_distance.h"

#include <openvdb/io/Stream.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/Morphology.h>
#include <openvdb/tools/Prune.h>
#include <openvdb/tools/SignedFloodFill.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>

namespace kerf {

namespace {

Vec3 worldOf(const openvdb::Coord& c, double voxel) {
    return Vec3(double(c.x()) * voxel, double(c.y()) * voxel, double(c.z()) * voxel);
}

/// The tape simplified over the voxels of the 8³ leaf at `origin` (interval evaluation decides
/// the min/max branches there; the result has the same value at each of those voxels), so a
/// model of thousands of primitives costs a few instructions per voxel, not all of them.
std::shared_ptr<const Tape> leafTape(const Tape& tape, const openvdb::Coord& origin, double voxel) {
    Interval box[3];
    for (int a = 0; a < 3; ++a)
        box[a] = Interval(double(origin[a]) * voxel, double(origin[a] + 7) * voxel);
    std::vector<Choice> choices;
    tape.evalInterval(box[0], box[1], box[2], choices);
    return tape.simplified(choices);
}

/// The stored value of a voxel at exact distance d (< band) with the implicit's sign (kerf's
/// f ≤ 0 inside, NaN outside); a voxel on the surface is inside for kerf and must be for
/// OpenVDB (v < 0).
float signedValue(double d, const Tape& tape, const openvdb::Coord& c, double voxel) {
    const bool inside = tape.eval(worldOf(c, voxel)) <= 0.0;
    const float v = std::max(float(d), float(voxel) * 1e-6f);
    return inside ? -v : v;
}

/// The band: every voxel nearer the mesh than band·voxel, found by growing from the voxels
/// nearest the vertices (each within √3/2 voxel of the mesh) through face neighbours; the
/// points nearer than the band form one connected shell round each connected part of the
/// mesh. Each round tests only the new neighbours of the last round's voxels, leaf by leaf
/// in parallel, and applies the results in leaf order, so the grid does not depend on the
/// threads. Returns the distance queries made.
uint64_t growBand(openvdb::FloatGrid& grid, const WatertightMesh& mesh,
                  const MeshDistance& distance, double voxel, double band, const Tape& tape) {
    const double width = band * voxel;
    using BoolAccessor = openvdb::tree::ValueAccessor<openvdb::BoolTree>;
    auto candidates = std::make_unique<openvdb::BoolTree>(false);
    openvdb::BoolTree visited(false);
    {
        BoolAccessor acc(*candidates);
        for (const Vec3& v : mesh.vertices)
            acc.setValueOn(openvdb::Coord(int(std::lround(v.x / voxel)),
                                          int(std::lround(v.y / voxel)),
                                          int(std::lround(v.z / voxel))));
    }
    struct Found {
        openvdb::Coord c;
        float value;
    };
    uint64_t queries = 0;
    openvdb::FloatGrid::Accessor out = grid.getAccessor();
    while (true) {
        visited.topologyUnion(*candidates);
        std::vector<openvdb::BoolTree::LeafNodeType*> leaves;
        candidates->getNodes(leaves);
        std::vector<std::vector<Found>> found(leaves.size());
        tbb::parallel_for(size_t(0), leaves.size(), [&](size_t i) {
            uint32_t hint = MeshDistance::kNoHint;  // the last voxel's nearest triangle
            std::shared_ptr<const Tape> local;      // made for the first voxel in the band
            for (auto it = leaves[i]->cbeginValueOn(); it; ++it) {
                const openvdb::Coord c = it.getCoord();
                const double d = distance.distance(worldOf(c, voxel), width, hint);
                if (!(d < width)) continue;
                if (!local) local = leafTape(tape, leaves[i]->origin(), voxel);
                found[i].push_back({c, signedValue(d, *local, c, voxel)});
            }
        });
        queries += candidates->activeVoxelCount();
        auto front = std::make_unique<openvdb::BoolTree>(false);
        BoolAccessor frontAcc(*front);
        for (const std::vector<Found>& list : found)
            for (const Found& f : list) {
                out.setValueOn(f.c, f.value);
                frontAcc.setValueOn(f.c);
            }
        if (front->activeVoxelCount() == 0) break;
        openvdb::tools::dilateActiveValues(*front, 1, openvdb::tools::NN_FACE,
                                           openvdb::tools::IGNORE_TILES);
        front->topologyDifference(visited);
        candidates = std::move(front);
    }
    return queries;
}

/// Every inactive voxel of the band's leaves gets ±background by the implicit's sign at it, so
/// the flood fill of the tiles reads true signs from the leaves' ends: OpenVDB's own fill of
/// leaf voxels scans from the active ones and put whole regions on the wrong side where a band
/// of one voxel is not closed along a scan line (measured: crossings 3.3 voxels off).
void inactiveSignsFromTape(openvdb::FloatGrid& grid, double voxel, float background,
                           const Tape& tape) {
    using Leaf = openvdb::FloatTree::LeafNodeType;
    std::vector<Leaf*> leaves;
    grid.tree().getNodes(leaves);
    tbb::parallel_for(size_t(0), leaves.size(), [&](size_t i) {
        if (leaves[i]->isValueMaskOn()) return;  // no inactive voxel
        const std::shared_ptr<const Tape> local = leafTape(tape, leaves[i]->origin(), voxel);
        for (auto it = leaves[i]->beginValueOff(); it; ++it)
            it.setValue(local->eval(worldOf(it.getCoord(), voxel)) <= 0.0 ? -background
                                                                          : background);
    });
}

}  // namespace

struct LevelSetFile::Impl {
    openvdb::GridPtrVec grids;
};

LevelSetFile::LevelSetFile() : mImpl(std::make_unique<Impl>()) { openvdb::initialize(); }
LevelSetFile::~LevelSetFile() = default;

LevelSetFile::Added LevelSetFile::add(const std::string& name, const WatertightMesh& mesh,
                                      double voxel, double band, const Tape& tape) {
    const float background = float(band * voxel);
    openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(background);
    grid->setTransform(openvdb::math::Transform::createLinearTransform(voxel));
    grid->setName(name);
    grid->setGridClass(openvdb::GRID_LEVEL_SET);
    Added added;
    if (!mesh.triangles.empty()) {
        const MeshDistance distance(mesh, voxel, band * voxel);
        added.distanceQueries = growBand(*grid, mesh, distance, voxel, band, tape);
        // Inactive voxels of leaves by the implicit; tiles (level 1 up) by OpenVDB's fill.
        inactiveSignsFromTape(*grid, voxel, background, tape);
        openvdb::tools::signedFloodFill(grid->tree(), true, 1, /*minLevel=*/1);
        openvdb::tools::pruneLevelSet(grid->tree());
        added.activeVoxels = grid->activeVoxelCount();
    }
    mImpl->grids.push_back(grid);
    return added;
}

std::string LevelSetFile::bytes() const {
    std::ostringstream out(std::ios_base::out | std::ios_base::binary);
    openvdb::io::Stream(out).write(mImpl->grids);
    std::string file = out.str();
    // The header holds a random UUID (36 characters after the magic number, the file and
    // library versions and a flag: byte 21). Same input, same bits: it becomes a hash of the
    // rest of the file, formatted as a UUID of version 8 (RFC 9562, "custom").
    constexpr size_t kAt = 21, kLength = 36;
    if (file.size() > kAt + kLength && file[kAt + 8] == '-' && file[kAt + 13] == '-' &&
        file[kAt + 18] == '-' && file[kAt + 23] == '-') {
        uint64_t h[2] = {0xcbf29ce484222325ull, 0x84222325cbf29ce4ull};  // FNV-1a, two seeds
        for (size_t i = kAt + kLength; i < file.size(); ++i)
            for (uint64_t& x : h) x = (x ^ uint8_t(file[i])) * 0x100000001b3ull;
        h[0] = (h[0] & ~0xf000ull) | 0x8000ull;                  // version 8 in the third group
        h[1] = (h[1] & ~(0xc000ull << 48)) | (0x8000ull << 48);  // the RFC's variant
        char uuid[40];
        std::snprintf(uuid, sizeof uuid, "%08x-%04x-%04x-%04x-%012llx", unsigned(h[0] >> 32),
                      unsigned(h[0] >> 16) & 0xffffu, unsigned(h[0]) & 0xffffu,
                      unsigned(h[1] >> 48), (unsigned long long)(h[1] & 0xffffffffffffull));
        file.replace(kAt, kLength, uuid, kLength);
    }
    return file;
}

}  // namespace kerf
