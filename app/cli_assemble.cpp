/// @file app/cli_assemble.cpp
/// @brief The checks are on rectangles only (no pixel is read twice): every pair of parts is
/// tested for overlap, and the holes are found on the grid of the parts' own edges, whose
/// cells are each wholly covered or wholly not.
#include "app/cli_assemble.h"

#include "app/exit_codes.h"
#include "app/output_paths.h"
#include "io/image.h"
#include "render/render.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <stdexcept>

namespace kerf::app {

namespace {

struct Part {
    std::string path;
    Image image;
    ImageWindow window;
    PixelRect rect() const {
        return {window.x, window.y, window.x + image.width, window.y + image.height};
    }
};

std::string text(const PixelRect& r) {
    return std::to_string(r.x0) + "," + std::to_string(r.y0) + "," + std::to_string(r.x1) + "," +
           std::to_string(r.y1);
}

Part readPart(const std::string& path) {
    const std::string ext = lowerExtension(path);
    if (ext == ".png" || ext == ".jpg" || ext == ".jpeg")
        throw UsageError("part '" + path +
                         "': a PNG or JPEG file holds the region alone, not its "
                         "place in the full image; render the regions to .exr (or .tif)");
    Part part;
    part.path = path;
    try {
        part.image = readImage(path, part.window);
    } catch (const ImageSupportError&) {
        throw;  // not the part's fault
    } catch (const std::runtime_error& e) {
        throw UsageError(std::string("part: ") + e.what());
    }
    return part;
}

/// The rectangles of the full image no part covers (the parts do not overlap), at most
/// `limit` of them, merged row-wise on the grid of the parts' edges; `more` counts the rest.
std::vector<PixelRect> holes(const std::vector<Part>& parts, int width, int height, size_t limit,
                             size_t& more) {
    std::vector<int> xs{0, width}, ys{0, height};
    for (const Part& p : parts) {
        const PixelRect r = p.rect();
        xs.insert(xs.end(), {r.x0, r.x1});
        ys.insert(ys.end(), {r.y0, r.y1});
    }
    for (std::vector<int>* v : {&xs, &ys}) {
        std::sort(v->begin(), v->end());
        v->erase(std::unique(v->begin(), v->end()), v->end());
    }
    const size_t nx = xs.size() - 1, ny = ys.size() - 1;
    const auto index = [](const std::vector<int>& v, int value) {
        return size_t(std::lower_bound(v.begin(), v.end(), value) - v.begin());
    };
    std::vector<char> covered(nx * ny, 0);  // then 2: already reported in a hole
    for (const Part& p : parts) {
        const PixelRect r = p.rect();
        for (size_t j = index(ys, r.y0); j < index(ys, r.y1); ++j)
            for (size_t i = index(xs, r.x0); i < index(xs, r.x1); ++i) covered[j * nx + i] = 1;
    }
    std::vector<PixelRect> found;
    more = 0;
    for (size_t j = 0; j < ny; ++j)
        for (size_t i = 0; i < nx; ++i) {
            if (covered[j * nx + i] != 0) continue;
            // Grow right, then down while the whole run of cells is open.
            size_t i1 = i + 1;
            while (i1 < nx && covered[j * nx + i1] == 0) ++i1;
            size_t j1 = j + 1;
            while (j1 < ny && std::all_of(&covered[j1 * nx + i], &covered[j1 * nx + i1],
                                          [](char c) { return c == 0; }))
                ++j1;
            for (size_t b = j; b < j1; ++b)
                std::fill(&covered[b * nx + i], &covered[b * nx + i1], char(2));
            if (found.size() < limit)
                found.push_back({xs[i], ys[j], xs[i1], ys[j1]});
            else
                ++more;
        }
    return found;
}

void checkTiling(const std::vector<Part>& parts) {
    const Part& first = parts.front();
    const int width = first.window.fullWidth, height = first.window.fullHeight;
    for (const Part& p : parts) {
        if (p.window.fullWidth != width || p.window.fullHeight != height)
            throw UsageError("parts of different images: '" + first.path + "' is part of a " +
                             std::to_string(width) + "x" + std::to_string(height) + " image, '" +
                             p.path + "' of a " + std::to_string(p.window.fullWidth) + "x" +
                             std::to_string(p.window.fullHeight) + " one");
        if (p.image.channels != first.image.channels)
            throw UsageError("parts with different channels: '" + first.path + "' has " +
                             std::to_string(first.image.channels) + ", '" + p.path + "' " +
                             std::to_string(p.image.channels));
        const PixelRect r = p.rect();
        if (!(intersect(r, {0, 0, width, height}) == r))
            throw UsageError("part '" + p.path + "' (pixels " + text(r) +
                             ") is not inside its full image");
    }
    for (size_t a = 0; a < parts.size(); ++a)
        for (size_t b = a + 1; b < parts.size(); ++b) {
            const PixelRect both = intersect(parts[a].rect(), parts[b].rect());
            if (!both.empty())
                throw UsageError("parts '" + parts[a].path + "' (pixels " + text(parts[a].rect()) +
                                 ") and '" + parts[b].path + "' (pixels " + text(parts[b].rect()) +
                                 ") overlap in " + text(both));
        }
    size_t more = 0;
    const std::vector<PixelRect> missing = holes(parts, width, height, 8, more);
    if (!missing.empty()) {
        std::string list;
        for (const PixelRect& r : missing) list += (list.empty() ? "" : ", ") + text(r);
        if (more > 0) list += " and " + std::to_string(more) + " more";
        throw UsageError("the parts do not cover the " + std::to_string(width) + "x" +
                         std::to_string(height) + " image: missing pixels " + list +
                         " (X0,Y0,X1,Y1, half-open)");
    }
}

}  // namespace

CLI::App* addAssembleCommand(CLI::App& parent, AssembleCommandLine& line) {
    CLI::App* cmd = parent.add_subcommand(
        "assemble",
        "Stitch region images (kerf render --region … -o PART.exr) into the full image; the "
        "parts must cover it exactly once");
    cmd->add_option("OUT", line.output,
                    "The full image; the format follows the extension (.png .jpg .exr .tif)")
        ->required();
    cmd->add_option("PART", line.parts,
                    "Region images, .exr or .tif (a .png holds no place in the full image)")
        ->required();
    return cmd;
}

int runAssemble(const AssembleCommandLine& line) {
    const std::string ext = lowerExtension(line.output);
    if (ext != ".png" && ext != ".jpg" && ext != ".jpeg" && ext != ".exr" && ext != ".tif" &&
        ext != ".tiff")
        throw UsageError("OUT '" + line.output + "': unknown image format '" + ext +
                         "' (use .png, .jpg, .exr or .tif)");
    for (const std::string& part : line.parts)
        if (samePath(part, line.output))
            throw UsageError("OUT '" + line.output + "' is also a part: it would be overwritten");
    checkOutputWritable(line.output);

    std::vector<Part> parts;
    for (const std::string& path : line.parts) parts.push_back(readPart(path));
    checkTiling(parts);

    const Part& first = parts.front();
    Image full(first.window.fullWidth, first.window.fullHeight, first.image.channels);
    for (const Part& p : parts)
        for (int y = 0; y < p.image.height; ++y)
            std::copy_n(
                &p.image.pixels[size_t(y) * p.image.width * p.image.channels],
                size_t(p.image.width) * p.image.channels,
                &full.pixels[(size_t(p.window.y + y) * full.width + p.window.x) * full.channels]);
    writeImage(full, line.output);
    return kExitSuccess;
}

}  // namespace kerf::app
