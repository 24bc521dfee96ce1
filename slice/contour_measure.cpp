// A contour's measures: the statistics of contouring added up, a loop's area and length.
#include "slice/contour.h"

#include <algorithm>
#include <cmath>

namespace kerf {

void ContourStats::add(const ContourStats& o) {
    cells += o.cells;
    boundaryLeaves += o.boundaryLeaves;
    simpleLeaves += o.simpleLeaves;
    pointEvals += o.pointEvals;
    repairedLoops += o.repairedLoops;
    flatCells += o.flatCells;
    budgetExceeded = budgetExceeded || o.budgetExceeded;
    depth = std::max(depth, o.depth);
}

double loopArea(const SectionLoop& loop) {
    const auto& p = loop.points;
    double a = 0.0;
    for (size_t i = 0, n = p.size(); i < n; ++i) {
        const auto& s = p[i];
        const auto& t = p[(i + 1) % n];
        a += s[0] * t[1] - t[0] * s[1];
    }
    return 0.5 * a;
}

double loopLength(const SectionLoop& loop) {
    const auto& p = loop.points;
    double l = 0.0;
    for (size_t i = 0, n = p.size(); i < n; ++i)
        l += std::hypot(p[(i + 1) % n][0] - p[i][0], p[(i + 1) % n][1] - p[i][1]);
    return l;
}

}  // namespace kerf
