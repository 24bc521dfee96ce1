/// @file io/section_svg.cpp
/// @brief sectionSvg: a section as SVG paths in model units. The viewBox is the drawing's
/// rectangle with v negated, and one group flips v back (scale(1,-1)), so every coordinate in
/// the file is the model's own, written exactly (io/number_text.h).
#include <algorithm>
#include <cstdio>
#include <set>

#include "io/number_text.h"
#include "io/section_writers.h"
#include "io/srgb.h"
#include "io/svg.h"

namespace kerf {
namespace {

/// The longer side of the drawing as shown, in CSS pixels: model units are often a few
/// millimetres or metres, both unreadable at one pixel per unit.
constexpr double kDisplaySize = 1000.0;

std::string svgColor(const std::array<double, 3>& linear) {
    char text[8];
    std::snprintf(text, sizeof text, "#%02x%02x%02x", srgbByte(float(linear[0])),
                  srgbByte(float(linear[1])), srgbByte(float(linear[2])));
    return text;
}

/// An XML id from a layer name: letters, digits, '-', '_' and '.' kept, anything else '_',
/// a leading digit (or nothing) prefixed by '_', and a repeat made unique with "-2", "-3"….
/// The exact name is kept in the group's <title>.
std::string uniqueId(const std::string& name, std::set<std::string>& used) {
    std::string id;
    for (char c : name) {
        const bool keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                          (c >= '0' && c <= '9') || c == '-' || c == '_' || c == '.';
        id += keep ? c : '_';
    }
    if (id.empty() || (id[0] >= '0' && id[0] <= '9') || id[0] == '-' || id[0] == '.') id = "_" + id;
    std::string candidate = id;
    for (int n = 2; used.count(candidate); ++n) candidate = id + "-" + std::to_string(n);
    used.insert(candidate);
    return candidate;
}

/// Path data: "M u v L u v u v … Z" per loop, every number exact. A loop of fewer than
/// three points encloses nothing and is left out (as in the DXF).
std::string pathData(const std::vector<SectionLoop>& loops) {
    std::string d;
    size_t points = 0;
    for (const SectionLoop& loop : loops) points += loop.points.size();
    d.reserve(points * 40);
    for (const SectionLoop& loop : loops) {
        if (loop.points.size() < 3) continue;
        for (size_t k = 0; k < loop.points.size(); ++k) {
            d += k == 0 ? "M " : (k == 1 ? " L " : " ");
            appendExactNumber(d, loop.points[k][0]);
            d += ' ';
            appendExactNumber(d, loop.points[k][1]);
        }
        d += " Z ";
    }
    if (!d.empty()) d.pop_back();
    return d;
}

/// A side of the view: the drawing's, or (for a degenerate one) the other side, or 1.
void viewSide(double& lo, double& hi, double other) {
    if (hi - lo > 0) return;
    const double half = 0.5 * (other > 0 ? other : 1.0);
    const double mid = 0.5 * (lo + hi);
    lo = mid - half;
    hi = mid + half;
}

}  // namespace

std::string sectionSvg(const SectionDrawing& drawing, bool outline) {
    double u0 = drawing.minU, u1 = drawing.maxU, v0 = drawing.minV, v1 = drawing.maxV;
    const double w0 = u1 - u0, h0 = v1 - v0;
    viewSide(u0, u1, h0);
    viewSide(v0, v1, w0);
    const double w = u1 - u0, h = v1 - v0;
    const double scale = kDisplaySize / std::max(w, h);
    SvgWriter svg(u0, -v1, w, h, w * scale, h * scale);
    svg.beginGroup({{"transform", "scale(1,-1)"}});
    std::set<std::string> ids;
    for (const SectionLayer& layer : drawing.layers) {
        svg.beginGroup({{"id", uniqueId(layer.name, ids)}});
        svg.element("title", {}, layer.name);
        const std::string color = svgColor(layer.color);
        SvgAttributes attributes;
        if (outline) {
            // One pixel at the displayed size, in model units (vector-effect's non-scaling
            // strokes would say it better, but librsvg and older Inkscape ignore it).
            attributes.insert(
                attributes.end(),
                {{"fill", "none"}, {"stroke", color}, {"stroke-width", exactNumber(1.0 / scale)}});
        } else {
            attributes.insert(attributes.end(), {{"fill", color}, {"fill-rule", "evenodd"}});
        }
        svg.path(attributes, pathData(layer.loops));
        svg.endGroup();
    }
    svg.endGroup();
    return svg.finish();
}

}  // namespace kerf
