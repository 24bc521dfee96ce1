/// @file app/stats_report.cpp
#include "app/stats_report.h"

#include "csg/format.h"

#include <algorithm>
#include <cinttypes>
#include <cstdio>
#include <ostream>
#include <string>

namespace kerf::app {

namespace {

std::string line(const char* label, const std::string& value) {
    char buffer[128];
    std::snprintf(buffer, sizeof buffer, "  %-22s %s\n", label, value.c_str());
    return buffer;
}

std::string count(uint64_t n) { return std::to_string(n); }

std::string seconds(double s) { return formatDouble("%.3f s", s); }

/// The octree's size, memory and pruning, for scenes that trace through one.
void printOctree(const RenderStats& s, uint64_t rays, std::ostream& out) {
    const OctreeStats& o = s.octree;
    out << line("octree objects", count(uint64_t(o.objects)) + ", finest level " +
                                      std::to_string(o.maxDepth) +
                                      formatDouble(", finest cell %.3g", o.finestCell));
    out << line("octree bricks", count(o.bricksBuilt) + " of " + count(o.bricks) +
                                     " built (8³ cells each, on first use)");
    out << line("octree cells", count(o.boundaryCells) + " boundary, " + count(o.fullBlocks) +
                                    " full blocks, " + count(o.cellsClassified) + " classified");
    out << line("octree memory", formatDouble("%.3g MB", double(o.memoryBytes) / 1e6) +
                                     " in grid and cells, besides " + count(o.distinctNodes) +
                                     " distinct pruned trees");
    if (o.fullTapeOps > 0)
        out << line("pruned tape length",
                    formatDouble("%.3g", double(o.prunedTapeOps) / double(o.boundaryCells)) +
                        formatDouble(" of %.3g ops per cell",
                                     double(o.fullTapeOps) / double(o.boundaryCells)));
    out << line(
        "cells visited / ray",
        formatDouble("%.3g", double(s.trace.cellsVisited) / double(std::max<uint64_t>(rays, 1))));
    out << line("octree build", seconds(s.secondsAccel) + " (coarse levels; bricks during trace)");
}

/// The phases' times and the ray rate.
void printTimes(const RunReport& report, uint64_t rays, std::ostream& out) {
    const RenderStats& s = report.render;
    out << line("parse + compile", seconds(report.secondsCompile));
    out << line("setup", seconds(s.secondsSetup));
    out << line("trace", seconds(s.secondsTrace));
    out << line("write", seconds(report.secondsWrite));
    const double total =
        report.secondsCompile + s.secondsSetup + s.secondsTrace + report.secondsWrite;
    out << line("total", seconds(total));
    if (s.secondsTrace > 0) {
        out << line("rays per second", formatDouble("%.4g", double(rays) / s.secondsTrace));
    }
}

}  // namespace

void printStats(const RunReport& report, std::ostream& out) {
    const RenderStats& s = report.render;
    const uint64_t rays = s.cameraRays + s.shadowRays + s.reflectionRays + s.refractionRays;

    out << "kerf statistics\n";
    out << line("image", std::to_string(report.width) + " x " + std::to_string(report.height));
    // The sampler takes an n×n grid, so the traced count can exceed the requested one.
    std::string samples = std::to_string(s.samplesPerPixel);
    if (s.samplesPerPixel != report.spp)
        samples += " (requested " + std::to_string(report.spp) + ")";
    out << line("samples per pixel",
                samples + ", " + samplerName(s.sampler) + ", " + filterName(s.filter) + " filter");
    const uint64_t pixels = uint64_t(report.width) * uint64_t(report.height);
    if (pixels > 0 && s.samplesTaken != pixels * uint64_t(std::max(s.samplesPerPixel, 1)))
        out << line("samples taken",
                    count(s.samplesTaken) + formatDouble(" (%.3g per pixel, adaptive)",
                                                         double(s.samplesTaken) / double(pixels)));
    out << line("threads", std::to_string(report.threads));
    out << line("tolerance", formatDouble("%.3g (relative)", s.tolerance));
    out << line("camera rays", count(s.cameraRays));
    out << line("shadow rays", count(s.shadowRays));
    out << line("reflection rays", count(s.reflectionRays));
    out << line("refraction rays", count(s.refractionRays));
    out << line("rays in total", count(rays));
    out << line("primitive tests", count(s.trace.primitiveTests));
    out << line("bounds tests", count(s.trace.boundsTests));
    out << line("root-finder steps", count(s.trace.rootSteps));
    out << line("interval evaluations", count(s.trace.intervalEvals));
    if (s.octree.objects > 0) printOctree(s, rays, out);
    if (s.beamsUsed && s.beams.pixels > 0)
        out << line(
            "camera beams",
            count(s.beams.slices) + " slices classified, " +
                formatDouble("%.3g per pixel", double(s.beams.slices) / double(s.beams.pixels)) +
                formatDouble(", mean start %.3g", s.beams.startSum / double(s.beams.pixels)));
    // Only scenes with meshes walk a triangle BVH (its root is visited by any ray that reaches
    // a mesh's box): others print nothing more.
    if (s.trace.meshNodes > 0 || s.trace.triangleTests > 0) {
        const double perRay = 1.0 / double(std::max<uint64_t>(rays, 1));
        out << line("mesh BVH nodes",
                    count(s.trace.meshNodes) +
                        formatDouble(" (%.3g per ray)", double(s.trace.meshNodes) * perRay));
        out << line("triangle tests",
                    count(s.trace.triangleTests) +
                        formatDouble(" (%.3g per ray)", double(s.trace.triangleTests) * perRay));
    }
    if (rays > 0)
        out << line("interval evals / ray",
                    formatDouble("%.3g", double(s.trace.intervalEvals) / double(rays)));
    printTimes(report, rays, out);
}

}  // namespace kerf::app
