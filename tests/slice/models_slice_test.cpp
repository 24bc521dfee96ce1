// Every model in models/ sliced to SVG, DXF and PNG by `kerf slice`, the three files checked
// against each other and against the section's own statistics: the DXF holds one closed
// LWPOLYLINE per contour, the SVG one path per layer, and the PNG's exact coverage, summed
// over its pixels, gives back the section's area.
#include "app/kerf_runner.h"
#include "io/image.h"

#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>

using namespace kerf::test;

namespace {

std::string readText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

size_t count(const std::string& text, const std::string& word) {
    size_t n = 0;
    for (size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) ++n;
    return n;
}

/// The number right after the first `label` in the --stats text.
double statistic(const std::string& err, const std::string& label) {
    const size_t at = err.find(label);
    REQUIRE(at != std::string::npos);
    return std::stod(err.substr(at + label.size()));
}

}  // namespace

TEST_CASE("every model slices to SVG, DXF and PNG that agree with its statistics") {
    TempDir dir;
    int models = 0;
    for (const auto& entry : fs::directory_iterator(modelsDir())) {
        if (entry.path().extension() != ".kerf") continue;
        const std::string model = entry.path().string(), name = entry.path().stem().string();
        INFO(name);
        // The first of these planes that meets the model (the gear lies in z = 0's plane).
        double area = 0.0, contours = 0.0, perimeter = 0.0;
        std::string plane;
        for (const char* candidate : {"y=0.5", "z=0"}) {
            const KerfRun run = runKerf(dir, {"slice", model, "--plane", candidate, "--tolerance",
                                              "1e-3", "-o", name + ".svg", "--stats"});
            INFO(run.err);
            REQUIRE(run.exitCode == 0);
            area = statistic(run.err, "total: area ");
            contours = statistic(run.err, "contours ");
            const std::string total = run.err.substr(run.err.find("total: area "));
            perimeter = statistic(total, "perimeter ");
            plane = candidate;
            if (area > 0.0) break;
        }
        REQUIRE(area > 0.0);
        ++models;
        // SVG: paths, closed, one per layer with loops.
        const std::string svg = readText(dir.file(name + ".svg"));
        CHECK(count(svg, "<path") >= 1);
        CHECK(count(svg, "Z") >= size_t(contours));
        // DXF: one closed polyline per contour, and a well-formed end.
        const KerfRun dxf = runKerf(
            dir, {"slice", model, "--plane", plane, "--tolerance", "1e-3", "-o", name + ".dxf"});
        REQUIRE(dxf.exitCode == 0);
        const std::string dxfText = readText(dir.file(name + ".dxf"));
        CHECK(count(dxfText, "LWPOLYLINE") == size_t(contours));
        CHECK(dxfText.find("EOF") != std::string::npos);
        // PNG: the coverage of every pixel is exact, so their sum times a pixel's area is the
        // polygons' area, up to 8-bit quantisation of alpha: half a code in each pixel the
        // boundary crosses, at most 2√2 per pixel length of boundary plus 4 per contour.
        const double pixel = 0.02;
        const KerfRun png = runKerf(dir, {"slice", model, "--plane", plane, "--tolerance", "1e-3",
                                          "-o", name + ".png", "--pixel", std::to_string(pixel)});
        REQUIRE(png.exitCode == 0);
        const kerf::Image image = kerf::readImage(dir.file(name + ".png"));
        REQUIRE(image.channels == 4);
        double covered = 0.0;
        for (size_t i = 3; i < image.pixels.size(); i += 4) covered += image.pixels[i];
        const double boundaryPixels = 2.0 * std::sqrt(2.0) * perimeter / pixel + 4.0 * contours;
        CHECK(std::fabs(covered * pixel * pixel - area) <=
              (0.5 / 255.0) * boundaryPixels * pixel * pixel + 1e-9 * area);
    }
    CHECK(models >= 10);
}
