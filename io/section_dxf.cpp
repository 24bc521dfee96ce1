/// @file io/section_dxf.cpp
/// @brief sectionDxf: a section as an ASCII DXF (AC1015). Only what readers need: a HEADER
/// (version, units, extent, next handle), TABLES with the CONTINUOUS line type and one LAYER
/// per section layer (its colour as the nearest AutoCAD Colour Index and as a true colour),
/// and ENTITIES, one closed LWPOLYLINE per loop, every number exact (io/number_text.h).
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <set>

#include "io/number_text.h"
#include "io/section_writers.h"
#include "io/srgb.h"

namespace kerf {
namespace {

using Rgb = std::array<int, 3>;

/// The AutoCAD Colour Index palette, 1 to 255 (index 0 and 7 are never chosen: 0 is "by
/// block", 7 is white or black by the background). 1–9 are named colours; 10–249 are 24 hues
/// 15° apart, each at five values (1, 0.65, 0.5, 0.3, 0.15), even indices fully saturated
/// and odd ones half; 250–255 are greys.
Rgb aciColor(int index) {
    static const Rgb named[10] = {{0, 0, 0},       {255, 0, 0},    {255, 255, 0}, {0, 255, 0},
                                  {0, 255, 255},   {0, 0, 255},    {255, 0, 255}, {255, 255, 255},
                                  {128, 128, 128}, {192, 192, 192}};
    if (index < 10) return named[index];
    if (index >= 250) {
        static const int grey[6] = {51, 91, 132, 173, 214, 255};
        const int g = grey[index - 250];
        return {g, g, g};
    }
    static const double values[5] = {1.0, 0.65, 0.5, 0.3, 0.15};
    const double hue = (index / 10 - 1) * 15.0;
    const double value = values[(index % 10) / 2];
    const double saturation = index % 2 ? 0.5 : 1.0;
    // HSV to RGB: each channel's distance in hue from its primary.
    Rgb rgb{};
    const double centers[3] = {0.0, 120.0, 240.0};
    for (int c = 0; c < 3; ++c) {
        double d = std::fabs(hue - centers[c]);
        d = std::min(d, 360.0 - d);
        const double level = std::clamp((120.0 - d) / 60.0, 0.0, 1.0);  // 1 within 60°
        rgb[c] = int(std::lround(255.0 * value * (1.0 - saturation * (1.0 - level))));
    }
    return rgb;
}

int nearestAci(const Rgb& rgb) {
    int best = 1;
    long bestDistance = -1;
    for (int index = 1; index <= 255; ++index) {
        if (index == 7) continue;
        const Rgb p = aciColor(index);
        long distance = 0;
        for (int c = 0; c < 3; ++c) distance += long(p[c] - rgb[c]) * (p[c] - rgb[c]);
        if (bestDistance < 0 || distance < bestDistance) {
            best = index;
            bestDistance = distance;
        }
    }
    return best;
}

/// A DXF layer name: the characters DXF forbids (< > / \ " : ; ? * | = ` and controls) as
/// '_', at most 255 characters, unique without regard to case (as AutoCAD compares them);
/// "0" is taken by the default layer.
std::string uniqueLayerName(const std::string& name, std::set<std::string>& used) {
    std::string out;
    for (char c : name) {
        const bool bad =
            (unsigned char)c < 32 || std::string("<>/\\\":;?*|=`").find(c) != std::string::npos;
        out += bad ? '_' : c;
    }
    if (out.empty()) out = "layer";
    out.resize(std::min<size_t>(out.size(), 240));
    const auto key = [](std::string s) {
        for (char& c : s) c = char(std::toupper((unsigned char)c));
        return s;
    };
    std::string candidate = out;
    for (int n = 2; used.count(key(candidate)); ++n) candidate = out + "-" + std::to_string(n);
    used.insert(key(candidate));
    return candidate;
}

class DxfText {
public:
    void pair(int code, const std::string& value) {
        appendCode(code);
        mText += value;
        mText += '\n';
    }
    void pair(int code, double value) {
        appendCode(code);
        appendExactNumber(mText, value);
        mText += '\n';
    }
    void integer(int code, long value) { pair(code, std::to_string(value)); }
    /// A new entity handle (code 5), hexadecimal.
    void handle() {
        char text[24];
        std::snprintf(text, sizeof text, "%X", mNextHandle++);
        pair(5, text);
    }
    unsigned nextHandle() const { return mNextHandle; }
    std::string& text() { return mText; }

    void reserve(size_t bytes) { mText.reserve(bytes); }

private:
    void appendCode(int code) {
        char text[16];
        const auto result = std::to_chars(text, text + sizeof text, code);
        mText.append(text, result.ptr);
        mText += '\n';
    }
    std::string mText;
    unsigned mNextHandle = 0x20;
};

/// The line-type table: CONTINUOUS only.
void writeLineTypeTable(DxfText& body) {
    body.pair(0, "TABLE");
    body.pair(2, "LTYPE");
    body.handle();
    body.pair(100, "AcDbSymbolTable");
    body.integer(70, 1);
    body.pair(0, "LTYPE");
    body.handle();
    body.pair(100, "AcDbSymbolTableRecord");
    body.pair(100, "AcDbLinetypeTableRecord");
    body.pair(2, "CONTINUOUS");
    body.integer(70, 0);
    body.pair(3, "Solid line");
    body.integer(72, 65);
    body.integer(73, 0);
    body.pair(40, 0.0);
    body.pair(0, "ENDTAB");
}

/// The layer table: the default layer "0" and one layer per section layer.
void writeLayerTable(DxfText& body, const SectionDrawing& drawing,
                     const std::vector<std::string>& names) {
    body.pair(0, "TABLE");
    body.pair(2, "LAYER");
    body.handle();
    body.pair(100, "AcDbSymbolTable");
    body.integer(70, long(drawing.layers.size()) + 1);
    // rgb null: the default layer's colour 7, white or black against the background.
    const auto layerRecord = [&](const std::string& name, const Rgb* rgb) {
        body.pair(0, "LAYER");
        body.handle();
        body.pair(100, "AcDbSymbolTableRecord");
        body.pair(100, "AcDbLayerTableRecord");
        body.pair(2, name);
        body.integer(70, 0);
        body.integer(62, rgb ? nearestAci(*rgb) : 7);
        if (rgb) body.integer(420, (long((*rgb)[0]) << 16) | ((*rgb)[1] << 8) | (*rgb)[2]);
        body.pair(6, "CONTINUOUS");
    };
    layerRecord("0", nullptr);
    for (size_t l = 0; l < drawing.layers.size(); ++l) {
        const auto& c = drawing.layers[l].color;
        const Rgb rgb = {srgbByte(float(c[0])), srgbByte(float(c[1])), srgbByte(float(c[2]))};
        layerRecord(names[l], &rgb);
    }
    body.pair(0, "ENDTAB");
}

/// One closed LWPOLYLINE per loop, on its layer.
void writeEntities(DxfText& body, const SectionDrawing& drawing,
                   const std::vector<std::string>& names) {
    for (size_t l = 0; l < drawing.layers.size(); ++l) {
        for (const SectionLoop& loop : drawing.layers[l].loops) {
            // A loop of fewer than three points encloses nothing; readers choke on it.
            if (loop.points.size() < 3) continue;
            body.pair(0, "LWPOLYLINE");
            body.handle();
            body.pair(100, "AcDbEntity");
            body.pair(8, names[l]);
            body.pair(100, "AcDbPolyline");
            body.integer(90, long(loop.points.size()));
            body.integer(70, 1);  // closed
            for (const auto& p : loop.points) {
                body.pair(10, p[0]);
                body.pair(20, p[1]);
            }
        }
    }
}

/// The HEADER section: version, next free handle, units and extent.
std::string headerSection(const SectionDrawing& drawing, unsigned nextHandle) {
    DxfText header;
    header.pair(0, "SECTION");
    header.pair(2, "HEADER");
    header.pair(9, "$ACADVER");
    header.pair(1, "AC1015");
    header.pair(9, "$HANDSEED");
    char seed[24];
    std::snprintf(seed, sizeof seed, "%X", nextHandle);
    header.pair(5, seed);
    // kerf's models have no unit; 0 is DXF's "unitless", so a reader keeps the numbers as
    // they are instead of converting from a guessed unit.
    header.pair(9, "$INSUNITS");
    header.integer(70, 0);
    header.pair(9, "$EXTMIN");
    header.pair(10, drawing.minU);
    header.pair(20, drawing.minV);
    header.pair(30, 0.0);
    header.pair(9, "$EXTMAX");
    header.pair(10, drawing.maxU);
    header.pair(20, drawing.maxV);
    header.pair(30, 0.0);
    header.pair(0, "ENDSEC");
    return header.text();
}

}  // namespace

std::string sectionDxf(const SectionDrawing& drawing) {
    DxfText body;  // tables and entities first: the header needs the next free handle
    size_t points = 0;
    for (const SectionLayer& layer : drawing.layers)
        for (const SectionLoop& loop : layer.loops) points += loop.points.size();
    body.reserve(4096 + points * 48);
    std::set<std::string> used = {"0"};
    std::vector<std::string> names;
    for (const SectionLayer& layer : drawing.layers)
        names.push_back(uniqueLayerName(layer.name, used));

    body.pair(0, "SECTION");
    body.pair(2, "TABLES");
    writeLineTypeTable(body);
    writeLayerTable(body, drawing, names);
    body.pair(0, "ENDSEC");

    body.pair(0, "SECTION");
    body.pair(2, "ENTITIES");
    writeEntities(body, drawing, names);
    body.pair(0, "ENDSEC");
    body.pair(0, "EOF");
    return headerSection(drawing, body.nextHandle()) + body.text();
}

}  // namespace kerf
