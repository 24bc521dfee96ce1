/// @file app/region_option.h
/// @brief `--region x0,y0,x1,y1`: parsed and checked for `kerf render` and `kerf-mpi render`,
/// and the place of a region's image in the full one when it is written.
#pragma once

#include "io/image.h"
#include "render/render.h"

#include <optional>
#include <string>

namespace CLI {
class Option;
}  // namespace CLI

namespace kerf::app {

/// The rectangle of `--region X0,Y0,X1,Y1` (whole numbers, X0 < X1, Y0 < Y1, none negative),
/// or nothing when the option was not given. Throws UsageError naming --region otherwise.
std::optional<PixelRect> parseRegion(const CLI::Option* option, const std::string& text);

/// Throws UsageError unless `region` lies inside the width × height image.
void checkRegionInside(const PixelRect& region, int width, int height);

/// Where the result's images sit in the full image (for io/image.h's windowed writes).
ImageWindow windowOf(const RenderResult& result);

}  // namespace kerf::app
