// Classifying the mesh lattice's blocks coarse to fine and sampling the boundary blocks.
// Regions are handled level by level (a list per level, processed in parallel, results kept
// in list order), so the result is the same whatever the thread count.
#include "volume/export/mesh_field.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace kerf {

namespace {

struct Region {
    std::array<int32_t, 3> block;
    int32_t size;
    std::shared_ptr<const Tape> tape;  ///< valid over the region's points
};

/// What one region turned into.
struct Outcome {
    enum Kind { Empty, Full, Split, Boundary } kind = Empty;
    std::vector<Choice> choices;
    std::shared_ptr<const Tape> childTape;
};

/// The box of lattice points [8·b, 8·(b + size) + extra] widened by `margin` points each side.
/// The corners are computed as the points are, and the coordinate is monotone in the index,
/// so the box holds every point of the range exactly as evaluated.
void regionBox(const MeshLattice& l, const std::array<int32_t, 3>& b, int32_t size, int margin,
               Interval box[3]) {
    for (int a = 0; a < 3; ++a) {
        const int64_t lo = int64_t(b[a]) * kMeshBlock - margin;
        const int64_t hi = (int64_t(b[a]) + size) * kMeshBlock + margin;
        box[a] = Interval(l.origin[a] + double(lo) * l.voxel, l.origin[a] + double(hi) * l.voxel);
    }
}

std::string voxelText(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

/// Classifies a region by its tape's interval over the region's box; a region split in
/// eight carries the tape its children use.
Outcome classifyRegion(const MeshLattice& lattice, const Region& r) {
    Interval box[3];
    regionBox(lattice, r.block, r.size, 0, box);
    Outcome o;
    const Interval v = r.tape->evalInterval(box[0], box[1], box[2], o.choices);
    switch (v.classify()) {
        case Classification::Empty: o.kind = Outcome::Empty; break;
        case Classification::Filled: o.kind = Outcome::Full; break;
        default:
            if (r.size == 1) {
                o.kind = Outcome::Boundary;
            } else {
                o.kind = Outcome::Split;
                // A new tape only where a min or max was decided: otherwise the
                // children share the parent's, and memory does not grow per region.
                const bool decided = std::any_of(o.choices.begin(), o.choices.end(),
                                                 [](Choice c) { return c != Choice::Both; });
                o.childTape = decided ? r.tape->simplified(o.choices) : r.tape;
            }
    }
    o.choices.clear();
    o.choices.shrink_to_fit();
    return o;
}

/// Lists the children of a split region that lie within the lattice's `blocks`.
void splitRegion(const Region& r, const Outcome& o, const std::array<int32_t, 3>& blocks,
                 std::vector<Region>& next) {
    const int32_t half = r.size / 2;
    for (int c = 0; c < 8; ++c) {
        const std::array<int32_t, 3> b{r.block[0] + (c & 1 ? half : 0),
                                       r.block[1] + (c & 2 ? half : 0),
                                       r.block[2] + (c & 4 ? half : 0)};
        // Regions past the lattice hold no solid: it lies within the bounds.
        if (b[0] >= blocks[0] || b[1] >= blocks[1] || b[2] >= blocks[2]) continue;
        next.push_back({b, half, o.childTape});
    }
}

/// Classifies the lattice's blocks coarse to fine: full regions go to field.full, and the
/// boundary blocks are returned (in level order).
std::vector<std::array<int32_t, 3>> classifyBlocks(SampledField& field,
                                                   const std::shared_ptr<const Tape>& tape) {
    const MeshLattice& lattice = field.lattice;
    std::array<int32_t, 3> blocks{};
    int32_t side = 1;
    for (int a = 0; a < 3; ++a) {
        blocks[a] = int32_t((lattice.points[a] + kMeshBlock - 1) / kMeshBlock);
        while (side < blocks[a]) side *= 2;
    }
    std::vector<Region> level{{{0, 0, 0}, side, tape}};
    std::vector<std::array<int32_t, 3>> boundary;
    // The split regions of a level may not hold more than 8× the cap's blocks, so a voxel
    // far too fine stops early instead of listing billions of regions.
    const uint64_t capBlocks = kMeshMaxVoxels / (kMeshBlock * kMeshBlock * kMeshBlock);
    while (!level.empty()) {
        std::vector<Outcome> out(level.size());
        tbb::parallel_for(size_t(0), level.size(),
                          [&](size_t i) { out[i] = classifyRegion(lattice, level[i]); });
        field.intervalEvaluations += level.size();
        std::vector<Region> next;
        for (size_t i = 0; i < level.size(); ++i) {
            const Region& r = level[i];
            const Outcome& o = out[i];
            if (o.kind == Outcome::Full) field.full.push_back({r.block, r.size});
            if (o.kind == Outcome::Boundary) boundary.push_back(r.block);
            if (o.kind == Outcome::Split) splitRegion(r, o, blocks, next);
        }
        if (next.size() > 8 * capBlocks || boundary.size() > capBlocks)
            throw MeshInputError("--voxel " + voxelText(lattice.voxel) +
                                 " is too fine for this model: more than " +
                                 std::to_string(kMeshMaxVoxels) +
                                 " voxels near its surface (the limit); use a larger --voxel");
        level = std::move(next);
    }
    return boundary;
}

/// Samples a boundary block with the whole tape simplified over the block widened by
/// kMeshTapeMargin voxels: the same tape serves vertex placement near the block later.
void sampleBoundaryBlock(const MeshLattice& lattice, const Tape& tape, BoundaryBlock& bb) {
    Interval box[3];
    regionBox(lattice, bb.block, 1, kMeshTapeMargin, box);
    std::vector<Choice> choices;
    tape.evalInterval(box[0], box[1], box[2], choices);
    bb.tape = tape.simplified(choices);
    bb.values.resize(kMeshBlock * kMeshBlock * kMeshBlock);
    const int64_t i0 = int64_t(bb.block[0]) * kMeshBlock;
    const int64_t j0 = int64_t(bb.block[1]) * kMeshBlock;
    const int64_t k0 = int64_t(bb.block[2]) * kMeshBlock;
    for (int x = 0; x < kMeshBlock; ++x)
        for (int y = 0; y < kMeshBlock; ++y)
            for (int z = 0; z < kMeshBlock; ++z) {
                Vec3 g;
                const double f = bb.tape->evalGradient(lattice.at(i0 + x, j0 + y, k0 + z), g);
                const double len = glm::length(g);
                // First-order distance in voxels; where the gradient is useless, the band.
                double d = f / (len * lattice.voxel);
                if (!std::isfinite(d)) d = f <= 0.0 ? -kMeshBand : kMeshBand;
                d = std::clamp(d, -double(kMeshBand), double(kMeshBand));
                // kerf's inside is f ≤ 0, OpenVDB's is value < isovalue (0): a point on
                // the surface is inside for both.
                float v = float(d);
                if (f <= 0.0 && !(v < 0.0f)) v = -1e-6f;
                if (!(f <= 0.0) && !(v > 0.0f)) v = 1e-6f;  // f > 0 or NaN: outside
                bb.values[size_t(valueIndex(x, y, z))] = v;
            }
}

}  // namespace

/// The lattice's planes sit this fraction of a voxel off the model's bounds. Models put faces
/// at round coordinates, often a whole number of voxels from the bounds: a face on a lattice
/// plane has its samples at f = 0, and a crease there gets vertices from two cell layers, which
/// crease placement sends to one point (an edge of four faces once joined). 2 − φ is as far from
/// every simple fraction of a voxel as a number can be.
constexpr double kLatticeShift = 0.3819660112501051;

MeshLattice meshLattice(const Bounds3& bounds, double voxel) {
    if (!std::isfinite(voxel) || !(voxel > 0.0))
        throw MeshInputError("--voxel must be a finite number greater than 0, not " +
                             voxelText(voxel));
    MeshLattice l;
    l.voxel = voxel;
    for (int a = 0; a < 3; ++a) {
        // At least two voxels of margin each side, so the surface lies strictly inside the
        // lattice; the lower margin is 2 + kLatticeShift voxels, so one more cell keeps the
        // upper one above two.
        const double cells = std::ceil((bounds.hi[a] - bounds.lo[a]) / voxel) + 5.0;
        if (!(cells < double(kMeshMaxAxisPoints)))
            throw MeshInputError(
                "--voxel " + voxelText(voxel) + " is too fine for this model: more than " +
                std::to_string(kMeshMaxAxisPoints) + " voxels along an axis of its bounds");
        l.points[a] = int64_t(cells) + 1;
        l.origin[a] = bounds.lo[a] - (2.0 + kLatticeShift) * voxel;
    }
    return l;
}

SampledField sampleField(const MeshLattice& lattice, std::shared_ptr<const Tape> tape) {
    SampledField field;
    field.lattice = lattice;
    field.tape = tape;
    std::vector<std::array<int32_t, 3>> boundary = classifyBlocks(field, tape);
    std::sort(boundary.begin(), boundary.end());
    field.boundary.resize(boundary.size());
    tbb::parallel_for(size_t(0), boundary.size(), [&](size_t i) {
        BoundaryBlock& bb = field.boundary[i];
        bb.block = boundary[i];
        sampleBoundaryBlock(lattice, *tape, bb);
    });
    field.intervalEvaluations += boundary.size();
    return field;
}

}  // namespace kerf
