/// @file accuracy/plot.h
/// @brief The benchmark's time-against-error plot as SVG, drawn by kerf itself: log-log, one
/// polyline per scene and method (colour = scene, dash = method), decade ticks, a legend.
#pragma once

#include <string>

#include "accuracy/bench.h"

namespace kerf {

struct AccuracyPlotOptions {
    /// x is the max relative error when false, the 99th percentile when true.
    bool useP99 = false;
    /// Errors below this (exact hits give 0) are drawn at it; the caption says so.
    double errorFloor = 1e-17;
    std::string title = "kerf: time per primary ray against hit-distance error";
};

/// A complete SVG document; one <polyline> per (scene, method) series, in row order.
std::string accuracyPlotSvg(const AccuracyBenchResult& result,
                            const AccuracyPlotOptions& options = {});

}  // namespace kerf
