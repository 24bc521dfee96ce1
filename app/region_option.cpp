/// @file app/region_option.cpp
#include "app/region_option.h"

#include "app/exit_codes.h"

#include <CLI/CLI.hpp>

#include <cerrno>
#include <climits>
#include <cstdlib>
#include <vector>

namespace kerf::app {

namespace {

/// One whole number 0 … INT_MAX, all of `text`.
std::optional<int> regionCount(const std::string& text) {
    if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos)
        return std::nullopt;
    errno = 0;
    const long long v = std::strtoll(text.c_str(), nullptr, 10);
    if (errno != 0 || v > INT_MAX) return std::nullopt;
    return int(v);
}

}  // namespace

std::optional<PixelRect> parseRegion(const CLI::Option* option, const std::string& text) {
    if (option == nullptr || option->count() == 0) return std::nullopt;
    const std::string usage =
        "--region expects X0,Y0,X1,Y1: whole pixel numbers, the half-open rectangle "
        "[X0, X1) x [Y0, Y1) (got '" +
        text + "')";
    std::vector<int> v;
    size_t start = 0;
    for (;;) {
        const size_t comma = text.find(',', start);
        const std::optional<int> n = regionCount(text.substr(start, comma - start));
        if (!n) throw UsageError(usage);
        v.push_back(*n);
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    if (v.size() != 4) throw UsageError(usage);
    const PixelRect r{v[0], v[1], v[2], v[3]};
    if (r.empty())
        throw UsageError("--region '" + text + "' is empty: it needs X0 < X1 and Y0 < Y1");
    return r;
}

void checkRegionInside(const PixelRect& r, int width, int height) {
    if (r.x1 > width || r.y1 > height)
        throw UsageError("--region " + std::to_string(r.x0) + "," + std::to_string(r.y0) + "," +
                         std::to_string(r.x1) + "," + std::to_string(r.y1) + " is not inside the " +
                         std::to_string(width) + "x" + std::to_string(height) +
                         " image (X1 at most " + std::to_string(width) + ", Y1 at most " +
                         std::to_string(height) + ")");
}

ImageWindow windowOf(const RenderResult& result) {
    return ImageWindow{result.region.x0, result.region.y0, result.fullWidth, result.fullHeight};
}

}  // namespace kerf::app
