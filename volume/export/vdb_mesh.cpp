// The sampled field as an OpenVDB float grid, meshed by OpenVDB's volume-to-mesh.
// Boundary blocks become leaves holding their samples. Every block next to one (the ring)
// becomes a leaf of its constant classification, so that every lattice cell whose corners
// change sign has its lowest corner in a leaf: volume-to-mesh only looks at cells of leaves,
// and a sign change between two tiles would otherwise leave a hole. Full regions are inactive
// tiles (−band); empty space is the background (+band).
#include "volume/export/vdb_mesh.h"

#include <openvdb/openvdb.h>
#include <openvdb/tools/VolumeToMesh.h>

#include <algorithm>

namespace kerf {

namespace {

using Block = std::array<int32_t, 3>;
static_assert(openvdb::FloatTree::LeafNodeType::DIM == kMeshBlock, "a block is one leaf");

openvdb::Coord leafOrigin(const Block& b) {
    return openvdb::Coord(b[0] * kMeshBlock, b[1] * kMeshBlock, b[2] * kMeshBlock);
}

}  // namespace

LatticePolygons polygonizeField(const SampledField& field, double adaptivity) {
    openvdb::FloatGrid grid(kMeshBand);
    openvdb::FloatTree& tree = grid.tree();
    for (const FullRegion& r : field.full) {
        const openvdb::Coord lo = leafOrigin(r.block);
        tree.fill(openvdb::CoordBBox(lo, lo.offsetBy(r.size * kMeshBlock - 1)), -kMeshBand,
                  /*active=*/false);
    }
    std::vector<Block> boundary;
    boundary.reserve(field.boundary.size());
    for (const BoundaryBlock& b : field.boundary) boundary.push_back(b.block);  // sorted
    std::vector<Block> ring;
    for (const Block& b : boundary)
        for (int dx = -1; dx <= 1; ++dx)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dz = -1; dz <= 1; ++dz) {
                    const Block n{b[0] + dx, b[1] + dy, b[2] + dz};
                    if (!std::binary_search(boundary.begin(), boundary.end(), n)) ring.push_back(n);
                }
    std::sort(ring.begin(), ring.end());
    ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
    // The ring's values come from the tiles (or the background) before any leaf is made.
    std::vector<float> ringValue(ring.size());
    for (size_t i = 0; i < ring.size(); ++i) ringValue[i] = tree.getValue(leafOrigin(ring[i]));
    for (size_t i = 0; i < ring.size(); ++i)
        tree.touchLeaf(leafOrigin(ring[i]))->fill(ringValue[i], /*active=*/true);
    for (const BoundaryBlock& b : field.boundary) {
        openvdb::FloatTree::LeafNodeType* leaf = tree.touchLeaf(leafOrigin(b.block));
        for (openvdb::Index n = 0; n < openvdb::FloatTree::LeafNodeType::SIZE; ++n)
            leaf->setValueOn(n, b.values[n]);  // leaf offsets are z fastest, as valueIndex
    }

    std::vector<openvdb::Vec3s> points;
    std::vector<openvdb::Vec3I> triangles;
    std::vector<openvdb::Vec4I> quads;
    openvdb::tools::volumeToMesh(grid, points, triangles, quads, 0.0, adaptivity);

    LatticePolygons out;
    out.leaves = tree.leafCount();
    out.points.reserve(points.size());
    for (const openvdb::Vec3s& p : points) out.points.emplace_back(p.x(), p.y(), p.z());
    out.triangles.reserve(triangles.size());
    out.quads.reserve(quads.size());
    // With inside negative, OpenVDB winds its polygons counter-clockwise seen from outside,
    // the convention of OBJ, PLY and STL (tests/volume check the sign of the volume).
    for (const openvdb::Vec3I& t : triangles) out.triangles.push_back({t[0], t[1], t[2]});
    for (const openvdb::Vec4I& q : quads) out.quads.push_back({q[0], q[1], q[2], q[3]});
    return out;
}

}  // namespace kerf
