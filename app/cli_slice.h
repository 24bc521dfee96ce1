/// @file app/cli_slice.h
/// @brief `kerf slice FILE (--plane A=V | --point P --normal N | --stack A=FROM:TO:STEP [--layers
/// A-B]) -o OUT.{svg,dxf,png} [--tolerance E] [--outline] [--width W | --pixel H] [--stats] [-q]`:
/// the section of a model's solids by a plane (slice/), written by the output's extension.
#pragma once

#include <string>

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace kerf::app {

struct SliceCommandLine {
    std::string model;
    std::string output;  ///< for --stack, a pattern with one %d (e.g. cut_%04d.svg)
    std::string plane;   ///< "z=0.5"
    std::string point;   ///< "x,y,z" with --normal
    std::string normal;
    std::string stack;  ///< "z=0:2.4:0.05"
    std::string
        layers;  ///< with --stack: "A-B" or "N", the layers kept (numbered from 0); empty: all
    double tolerance = 1e-7;  ///< relative to the model's size
    bool outline = false;     ///< SVG: strokes only
    int width = 0;            ///< PNG: pixels across the section (default 1024 for the longer side)
    double pixel = 0.0;       ///< PNG: pixel size in model units (instead of --width)
    bool stats = false;
    bool quiet = false;
    /// With --stack, this process slices only every `parts`-th of the kept layers, starting at
    /// the `part`-th (kerf-mpi shares a stack out across its ranks this way).
    int part = 0;
    int parts = 1;
    CLI::Option* widthOption = nullptr;
    CLI::Option* pixelOption = nullptr;
    CLI::Option* layersOption = nullptr;
};

/// Adds the `slice` subcommand to `parent`, parsing into `line`.
CLI::App* addSliceCommand(CLI::App& parent, SliceCommandLine& line);

/// Runs the command; returns the exit code. Throws UsageError for bad options and lets
/// FileWriteError through to main().
int runSlice(const SliceCommandLine& line);

}  // namespace kerf::app
