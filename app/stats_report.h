/// @file app/stats_report.h
/// @brief The `--stats` report of `kerf render`: settings in force, work counters and the
/// time spent in each stage.
#pragma once

#include "render/render.h"

#include <iosfwd>

namespace kerf::app {

struct RunReport {
    int width = 0;
    int height = 0;
    int spp = 0;      ///< requested; RenderStats::samplesPerPixel is what was traced
    int threads = 0;  ///< resolved: never 0
    RenderStats render;
    double secondsCompile = 0;  ///< parse + compile
    double secondsWrite = 0;    ///< every output written
};

void printStats(const RunReport& report, std::ostream& out);

}  // namespace kerf::app
