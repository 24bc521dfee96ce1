/// @file render/primary_beams.h
/// @brief Coherent primary rays (issue 8 §4): a tile's camera rays traced as one beam. An
/// interval evaluation of every object over the box that bounds a tile's rays between two
/// distances proves that stretch empty for all of them at once; stretches that cannot be
/// proved empty split the tile in four, down to small blocks of pixels. Each pixel's camera
/// ray then starts where its block's empty stretch ends, so its own search (octree walk, root
/// isolation) begins near the surface. No ray is moved past a surface: the start is a
/// distance before which no point of any ray through the block is inside any object.
#pragma once

#include "csg/tree/node.h"
#include "render/camera.h"
#include "volume/octree/octree.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace kerf {

/// `--beams`: whether camera rays start where their tile's beam proved space empty.
enum class BeamMode {
    Auto,  ///< when beamsPay: implicit objects only, few primitives, the eye outside all bounds
    On,    ///< whenever the eye is outside every object's bounds
    Off,
};
const char* beamModeName(BeamMode mode);
std::optional<BeamMode> parseBeamMode(const std::string& name);

/// What the beams cost and gained (`--stats`).
struct BeamStats {
    uint64_t slices = 0;    ///< interval classifications of frustum slices
    uint64_t pixels = 0;    ///< pixels given a start
    double startSum = 0.0;  ///< sum of the starts given (mean = startSum / pixels)
    BeamStats& operator+=(const BeamStats& o) {
        slices += o.slices;
        pixels += o.pixels;
        startSum += o.startSum;
        return *this;
    }
};

/// Blocks of this many pixels on a side are the finest beams; a tile is split down to them.
constexpr int kBeamFinest = 4;
/// Slices one beam may classify before it stops and hands its pixels the start so far.
constexpr int kBeamMaxSlices = 48;
/// Objects whose primitives together exceed this make every slice cost more than the rays
/// it would spare (a union's interval value has no bounds to skip children by).
constexpr int64_t kBeamMaxPrimitives = 64;

/// Whether the default rule turns beams on: every object with finite bounds is an implicit
/// solid that the octree rule takes (octreePays: its rays cost root isolation, which a later
/// start shortens; closed-form objects cost a slice more than they save a ray), the objects
/// have at most kBeamMaxPrimitives primitives, and the eye is outside every object's bounds.
bool beamsPay(const std::vector<NodePtr>& objects, const OctreeOptions& octree);

class PrimaryBeams {
public:
    /// objects: the scene's objects in world space (before acceleration: their interval
    /// values are what is evaluated). Unusable (enabled() false) where the eye is inside some
    /// object's bounds: there is no empty stretch to prove in front of it.
    PrimaryBeams(const Camera& camera, const std::vector<NodePtr>& objects);

    bool enabled() const { return mEnabled; }

    /// For the pixels x0 ≤ i < x1, y0 ≤ j < y1: start[(j − y0)·(x1 − x0) + (i − x0)] is a
    /// distance up to which every camera ray through the pixel (any position in it) is outside
    /// every object.
    void tileStarts(int x0, int y0, int x1, int y1, double* start, BeamStats& stats) const;

private:
    /// Whether the box holds no point inside any object (every object's bounds miss it or its
    /// interval value is > 0 over it).
    bool emptyIn(const Bounds3& box) const;
    void beam(int x0, int y0, int x1, int y1, double t, int tileX0, int tileY0, int tileWidth,
              double* start, BeamStats& stats) const;

    const Camera& mCamera;
    std::vector<NodePtr> mObjects;
    std::vector<Bounds3> mBounds;
    double mFirstReach = 0.0;  ///< the nearest finite object bounds' distance from the eye
    double mLastReach = 0.0;   ///< the farthest finite object bounds' distance
    bool mUnbounded = false;   ///< some object has infinite bounds (a half-space)
    bool mEnabled = false;
};

}  // namespace kerf
