/// @file slice/slice.h
/// @brief The front door of slice/: a scene cut by a plane (or a stack of parallel planes)
/// into an io SectionDrawing, one layer per material, with statistics.
///
/// Each bounded object is contoured on its own (slice/contour.h) over the plane's part of its
/// bounds; unbounded objects (a floor half-space) have no finite section and are left out with
/// a note. A region (an outer loop and the holes directly inside it) takes the material at a
/// point just inside its outer loop (slice/material_at.h): where two materials of one object
/// touch, the region keeps one colour.
#pragma once

#include "io/section_writers.h"
#include "scene/scene.h"
#include "slice/contour.h"
#include "slice/plane.h"

#include <memory>
#include <string>
#include <vector>

namespace kerf {

struct SliceOptions {
    /// Relative to the model's size (the largest extent of the bounded objects' bounds).
    double tolerance = 1e-7;
};

struct RegionStats {
    std::string material;
    double area = 0.0;       ///< outer loop's area minus its holes'
    double perimeter = 0.0;  ///< outer loop and holes
    int holes = 0;
};

struct SliceStats {
    std::vector<RegionStats> regions;
    double area = 0.0;
    double perimeter = 0.0;
    size_t contours = 0;  ///< loops, outer and holes
    size_t holes = 0;
    ContourStats contour;
    double contourSeconds = 0.0;  ///< quadtree, root finding, loop linking
    double regionSeconds = 0.0;   ///< grouping holes, materials
};

struct SliceResult {
    SectionDrawing drawing;
    SliceStats stats;
};

/// A scene prepared for a family of parallel planes: each object's tape over the plane
/// coordinates is compiled once and shared by every layer (slice() is thread safe).
class SceneSlicer {
public:
    SceneSlicer(const Scene& scene, const SlicePlane& family, const SliceOptions& options);
    ~SceneSlicer();

    /// The section at offset w along the family's normal (SlicePlane::w).
    SliceResult slice(double w) const;
    /// The sections at each offset, in parallel; results in the offsets' order.
    std::vector<SliceResult> sliceMany(const std::vector<double>& offsets) const;

    double modelSize() const { return mModelSize; }
    double absoluteTolerance() const { return mTolerance; }
    double compileSeconds() const { return mCompileSeconds; }
    /// Things the user should hear about (unbounded objects left out).
    const std::vector<std::string>& notes() const { return mNotes; }

private:
    struct Object;
    const Scene& mScene;
    SlicePlane mFamily;
    std::vector<Object> mObjects;
    Bounds3 mBounds;
    double mModelSize = 1.0;
    double mTolerance = 1e-7;
    double mCompileSeconds = 0.0;
    std::vector<std::string> mNotes;
};

}  // namespace kerf
