/// @file render/primary_beams.cpp
/// @brief Tiles of camera rays proved empty slice by slice, split where they cannot be.
#include "render/primary_beams.h"

#include <algorithm>
#include <cmath>

namespace kerf {
namespace {

/// The distance from p to the box (0 inside it).
double distanceTo(const Bounds3& box, const Vec3& p) {
    double sum = 0.0;
    for (int a = 0; a < 3; ++a) {
        const double d = std::max({box.lo[a] - p[a], 0.0, p[a] - box.hi[a]});
        sum += d * d;
    }
    return std::sqrt(sum);
}

/// The distance from p to the farthest corner of the box.
double farthestCorner(const Bounds3& box, const Vec3& p) {
    double sum = 0.0;
    for (int a = 0; a < 3; ++a) {
        const double d = std::max(std::fabs(box.lo[a] - p[a]), std::fabs(box.hi[a] - p[a]));
        sum += d * d;
    }
    return std::sqrt(sum);
}

bool insideSomeFiniteBounds(const std::vector<NodePtr>& objects, const Vec3& eye) {
    for (const NodePtr& o : objects) {
        const Bounds3& b = o->bounds();
        if (b.finite() && distanceTo(b, eye) == 0.0) return true;
    }
    return false;
}

}  // namespace

const char* beamModeName(BeamMode mode) {
    switch (mode) {
        case BeamMode::Auto: return "auto";
        case BeamMode::On: return "on";
        case BeamMode::Off: return "off";
    }
    return "?";
}

std::optional<BeamMode> parseBeamMode(const std::string& name) {
    for (BeamMode m : {BeamMode::Auto, BeamMode::On, BeamMode::Off})
        if (name == beamModeName(m)) return m;
    return std::nullopt;
}

bool beamsPay(const std::vector<NodePtr>& objects, const OctreeOptions& octree) {
    int64_t primitives = 0;
    bool implicit = false;
    for (const NodePtr& o : objects) {
        primitives += o->primitiveCount();
        if (!o->bounds().finite()) continue;
        if (!octreePays(o, octree)) return false;
        implicit = true;
    }
    return implicit && primitives <= kBeamMaxPrimitives &&
           !insideSomeFiniteBounds(objects, octree.eye);
}

PrimaryBeams::PrimaryBeams(const Camera& camera, const std::vector<NodePtr>& objects)
    : mCamera(camera), mObjects(objects) {
    mFirstReach = kInf;
    bool anyFinite = false;
    for (const NodePtr& o : mObjects) {
        const Bounds3& b = o->bounds();
        mBounds.push_back(b);
        if (b.empty()) continue;
        if (!b.finite()) {
            mUnbounded = true;
            continue;
        }
        anyFinite = true;
        mFirstReach = std::min(mFirstReach, distanceTo(b, camera.eye()));
        mLastReach = std::max(mLastReach, farthestCorner(b, camera.eye()));
    }
    // The first slice reaches to the nearest finite bounds; without any, or with the eye
    // inside some, there is nothing to prove empty in front of the eye.
    mEnabled = anyFinite && mFirstReach > 0.0 && std::isfinite(mFirstReach);
}

bool PrimaryBeams::emptyIn(const Bounds3& box) const {
    const IntervalVec3 region{{box.lo.x, box.hi.x}, {box.lo.y, box.hi.y}, {box.lo.z, box.hi.z}};
    for (size_t k = 0; k < mObjects.size(); ++k) {
        if (Bounds3::overlap(mBounds[k], box).empty()) continue;
        if (mObjects[k]->valueInterval(region).classify() != Classification::Empty) return false;
    }
    return true;
}

void PrimaryBeams::tileStarts(int x0, int y0, int x1, int y1, double* start,
                              BeamStats& stats) const {
    beam(x0, y0, x1, y1, 0.0, x0, y0, x1 - x0, start, stats);
}

void PrimaryBeams::beam(int x0, int y0, int x1, int y1, double t, int tileX0, int tileY0,
                        int tileWidth, double* start, BeamStats& stats) const {
    // Slices about as deep as the beam is wide at their distance.
    const double growth = 1.0 + std::max(x1 - x0, y1 - y0) * mCamera.pixelAngle();
    for (int slices = 0; slices < kBeamMaxSlices; ++slices) {
        if (!mUnbounded && t >= mLastReach) break;  // past every object: nothing more to prove
        const double tb = t == 0.0 ? mFirstReach : t * growth;
        ++stats.slices;
        if (emptyIn(mCamera.frustumSlice(x0, y0, x1, y1, t, tb))) {
            t = tb;
            continue;
        }
        if (x1 - x0 <= kBeamFinest && y1 - y0 <= kBeamFinest) break;
        const int mx = x1 - x0 > kBeamFinest ? (x0 + x1) / 2 : x1;
        const int my = y1 - y0 > kBeamFinest ? (y0 + y1) / 2 : y1;
        const int xs[3] = {x0, mx, x1}, ys[3] = {y0, my, y1};
        for (int a = 0; a < 2; ++a)
            for (int b = 0; b < 2; ++b)
                if (xs[a] < xs[a + 1] && ys[b] < ys[b + 1])
                    beam(xs[a], ys[b], xs[a + 1], ys[b + 1], t, tileX0, tileY0, tileWidth, start,
                         stats);
        return;
    }
    for (int j = y0; j < y1; ++j)
        for (int i = x0; i < x1; ++i) start[(j - tileY0) * tileWidth + (i - tileX0)] = t;
    const uint64_t n = uint64_t(x1 - x0) * uint64_t(y1 - y0);
    stats.pixels += n;
    stats.startSum += t * double(n);
}

}  // namespace kerf
