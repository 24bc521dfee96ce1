// The surface area of a solid in voxel faces, from interval-classified regions, level by level
// (results in list order, so the same whatever the thread count).
#include "volume/export/voxelize_estimate.h"

#include "csg/interval/interval.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace kerf {

namespace {

struct EstimateRegion {
    std::array<int64_t, 3> corner;  ///< in regions
    int64_t size;                   ///< in regions
    std::shared_ptr<const Tape> tape;
};

constexpr size_t kMaxLevelRegions = size_t(1) << 21;

}  // namespace

BandEstimate estimateBand(std::shared_ptr<const Tape> tape, const Bounds3& bounds, double voxel,
                          double band) {
    BandEstimate estimate;
    const double side = voxel * kEstimateRegion;  // one region, model units
    std::array<int64_t, 3> count{};
    int64_t top = 1;
    for (int a = 0; a < 3; ++a) {
        count[a] = std::max<int64_t>(1, int64_t(std::ceil((bounds.hi[a] - bounds.lo[a]) / side)));
        while (top < count[a]) top *= 2;
    }
    std::vector<EstimateRegion> level{{{0, 0, 0}, top, std::move(tape)}};
    std::vector<EstimateRegion> next;
    int64_t size = top;
    while (true) {
        std::vector<std::shared_ptr<const Tape>> childTape(level.size());
        std::vector<char> boundary(level.size(), 0);
        tbb::parallel_for(size_t(0), level.size(), [&](size_t i) {
            const EstimateRegion& r = level[i];
            Interval box[3];
            for (int a = 0; a < 3; ++a)
                box[a] = Interval(bounds.lo[a] + double(r.corner[a]) * side,
                                  bounds.lo[a] + double(r.corner[a] + r.size) * side);
            std::vector<Choice> choices;
            const Interval v = r.tape->evalInterval(box[0], box[1], box[2], choices);
            if (v.classify() != Classification::Empty && v.classify() != Classification::Filled) {
                boundary[i] = 1;
                const bool decided = std::any_of(choices.begin(), choices.end(),
                                                 [](Choice c) { return c != Choice::Both; });
                childTape[i] = decided ? r.tape->simplified(choices) : r.tape;
            }
        });
        estimate.cells += level.size();
        const double n = double(std::count(boundary.begin(), boundary.end(), 1));
        if (size == 1 || n * 8 > double(kMaxLevelRegions)) {
            const double faces = double(size) * kEstimateRegion;
            estimate.area = n * faces * faces / 1.5;
            break;
        }
        next.clear();
        const int64_t half = size / 2;
        for (size_t i = 0; i < level.size(); ++i) {
            if (!boundary[i]) continue;
            const EstimateRegion& r = level[i];
            for (int c = 0; c < 8; ++c) {
                const std::array<int64_t, 3> b{r.corner[0] + (c & 1 ? half : 0),
                                               r.corner[1] + (c & 2 ? half : 0),
                                               r.corner[2] + (c & 4 ? half : 0)};
                if (b[0] >= count[0] || b[1] >= count[1] || b[2] >= count[2]) continue;
                next.push_back({b, half, childTape[i]});
            }
        }
        level.swap(next);
        size = half;
        if (level.empty()) break;  // nothing crosses: no surface
    }
    estimate.voxels = estimate.area * 2.0 * band;
    return estimate;
}

}  // namespace kerf
