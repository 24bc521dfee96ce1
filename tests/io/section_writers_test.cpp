/// @file tests/io/section_writers_test.cpp
/// @brief sectionSvg and sectionDxf read back by small readers in this file (a tag reader for
/// the SVG, a group-code reader for the DXF) to the same loops (bit for bit: the numbers are
/// written exactly), layers, colours and orientations.
#include "io/section_writers.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>

#include "io/srgb.h"

using namespace kerf;

namespace {

// ---- a small SVG reader: tags with attributes, and the text between them ----

struct Tag {
    std::string name;  ///< "/g" for a closing tag
    std::map<std::string, std::string> attributes;
    std::string textAfter;
};

std::string unescape(const std::string& s) {
    std::string out;
    for (size_t k = 0; k < s.size(); ++k) {
        if (s[k] != '&') {
            out += s[k];
            continue;
        }
        const size_t end = s.find(';', k);
        const std::string entity = s.substr(k + 1, end - k - 1);
        out += entity == "amp" ? '&' : entity == "lt" ? '<' : entity == "gt" ? '>' : '"';
        k = end;
    }
    return out;
}

std::vector<Tag> readTags(const std::string& xml) {
    std::vector<Tag> tags;
    size_t k = 0;
    while ((k = xml.find('<', k)) != std::string::npos) {
        const size_t end = xml.find('>', k);
        REQUIRE(end != std::string::npos);
        std::string inside = xml.substr(k + 1, end - k - 1);
        if (!inside.empty() && inside.back() == '/') inside.pop_back();
        Tag tag;
        size_t p = inside.find_first_of(" \n");
        tag.name = inside.substr(0, p);
        while (p != std::string::npos && p < inside.size()) {
            const size_t eq = inside.find('=', p);
            if (eq == std::string::npos) break;
            const size_t nameStart = inside.find_first_not_of(" \n", p);
            const size_t q1 = inside.find('"', eq), q2 = inside.find('"', q1 + 1);
            tag.attributes[inside.substr(nameStart, eq - nameStart)] =
                unescape(inside.substr(q1 + 1, q2 - q1 - 1));
            p = q2 + 1;
        }
        const size_t next = xml.find('<', end);
        tag.textAfter = unescape(xml.substr(end + 1, next - end - 1));
        tags.push_back(tag);
        k = end;
    }
    return tags;
}

/// Path data "M x y L x y … Z …" back to loops.
std::vector<SectionLoop> readPath(const std::string& d) {
    std::vector<SectionLoop> loops;
    std::istringstream in(d);
    std::string token;
    while (in >> token) {
        if (token == "M") loops.emplace_back();
        if (token == "M" || token == "L" || token == "Z") continue;
        const double u = std::strtod(token.c_str(), nullptr);
        in >> token;
        loops.back().points.push_back({u, std::strtod(token.c_str(), nullptr)});
    }
    return loops;
}

struct ReadLayer {
    std::string name;
    std::array<int, 3> rgb{};
    int aci = 0;
    std::vector<SectionLoop> loops;
};

std::array<int, 3> expectedRgb(const std::array<double, 3>& linear) {
    return {srgbByte(float(linear[0])), srgbByte(float(linear[1])), srgbByte(float(linear[2]))};
}

double signedArea(const SectionLoop& loop) {
    double twice = 0;
    for (size_t k = 0, n = loop.points.size(); k < n; ++k) {
        const auto& a = loop.points[k];
        const auto& b = loop.points[(k + 1) % n];
        twice += a[0] * b[1] - a[1] * b[0];
    }
    return twice / 2;
}

struct SvgRead {
    std::string viewBox, transform;
    std::vector<ReadLayer> layers;
    std::vector<std::map<std::string, std::string>> paths;
};

SvgRead readSvg(const std::string& svg) {
    SvgRead out;
    const std::vector<Tag> tags = readTags(svg);
    REQUIRE(!tags.empty());
    CHECK(tags.front().name == "svg");
    CHECK(tags.back().name == "/svg");
    int depth = 0;
    for (const Tag& tag : tags) {
        if (tag.name == "svg") out.viewBox = tag.attributes.at("viewBox");
        if (tag.name == "g" && tag.attributes.count("transform"))
            out.transform = tag.attributes.at("transform");
        if (tag.name == "g" && tag.attributes.count("id")) out.layers.emplace_back();
        if (tag.name == "title") out.layers.back().name = tag.textAfter;
        if (tag.name == "path") {
            const std::string color =
                tag.attributes.count("fill") && tag.attributes.at("fill") != "none"
                    ? tag.attributes.at("fill")
                    : tag.attributes.at("stroke");
            REQUIRE(color.size() == 7);
            for (int c = 0; c < 3; ++c)
                out.layers.back().rgb[c] =
                    int(std::strtol(color.substr(1 + 2 * c, 2).c_str(), nullptr, 16));
            out.layers.back().loops = readPath(tag.attributes.at("d"));
            out.paths.push_back(tag.attributes);
        }
        if (tag.name == "g") ++depth;
        if (tag.name == "/g") --depth;
    }
    CHECK(depth == 0);
    return out;
}

// ---- a small DXF reader: group-code pairs ----

struct DxfRead {
    std::map<std::string, std::vector<std::string>> header;  ///< $VAR → its values
    std::vector<ReadLayer> layers;
    std::vector<std::string> sections;
};

DxfRead readDxf(const std::string& dxf) {
    std::istringstream in(dxf);
    std::vector<std::pair<int, std::string>> pairs;
    std::string code, value;
    while (std::getline(in, code) && std::getline(in, value))
        pairs.push_back({std::stoi(code), value});
    REQUIRE(!pairs.empty());
    CHECK(pairs.back() == std::pair<int, std::string>{0, "EOF"});
    DxfRead out;
    std::map<std::string, size_t> layerIndex;
    std::string section, variable;
    int openTables = 0;
    for (size_t k = 0; k < pairs.size(); ++k) {
        const auto& [c, v] = pairs[k];
        if (c == 0 && v == "SECTION") {
            CHECK(section.empty());
            section = pairs[k + 1].second;
            out.sections.push_back(section);
        } else if (c == 0 && v == "ENDSEC") {
            section.clear();
        } else if (c == 0 && v == "TABLE") {
            ++openTables;
        } else if (c == 0 && v == "ENDTAB") {
            --openTables;
        } else if (section == "HEADER" && c == 9) {
            variable = v;
        } else if (section == "HEADER" && c != 0) {
            out.header[variable].push_back(v);
        } else if (section == "TABLES" && c == 0 && v == "LAYER") {
            ReadLayer layer;
            for (size_t m = k + 1; m < pairs.size() && pairs[m].first != 0; ++m) {
                if (pairs[m].first == 2) layer.name = pairs[m].second;
                if (pairs[m].first == 62) layer.aci = std::stoi(pairs[m].second);
                if (pairs[m].first == 420) {
                    const long rgb = std::stol(pairs[m].second);
                    layer.rgb = {int(rgb >> 16), int((rgb >> 8) & 255), int(rgb & 255)};
                }
            }
            layerIndex[layer.name] = out.layers.size();
            out.layers.push_back(layer);
        } else if (section == "ENTITIES" && c == 0 && v == "LWPOLYLINE") {
            SectionLoop loop;
            std::string layer;
            long count = -1, flags = 0;
            size_t m = k + 1;
            for (; m < pairs.size() && pairs[m].first != 0; ++m) {
                const auto& [cm, vm] = pairs[m];
                if (cm == 8) layer = vm;
                if (cm == 90) count = std::stol(vm);
                if (cm == 70) flags = std::stol(vm);
                if (cm == 10) loop.points.push_back({std::strtod(vm.c_str(), nullptr), 0.0});
                if (cm == 20) loop.points.back()[1] = std::strtod(vm.c_str(), nullptr);
            }
            CHECK(count == long(loop.points.size()));
            CHECK((flags & 1) == 1);  // closed
            REQUIRE(layerIndex.count(layer) == 1);
            out.layers[layerIndex[layer]].loops.push_back(loop);
        }
    }
    CHECK(section.empty());
    CHECK(openTables == 0);
    return out;
}

/// A drawing with awkward numbers, a hole, two layers (one with a name that needs escaping
/// or replacing), a layer with no loops, and a repeated name.
SectionDrawing sampleDrawing() {
    SectionDrawing d;
    d.minU = -1.25;
    d.maxU = 3.0000000000000004;
    d.minV = 0.1;
    d.maxV = 2.4;
    SectionLayer clay{"clay", {0.8, 0.5, 0.3}, {}};
    clay.loops.push_back({{{-1.2, 0.1}, {1.2, 0.1}, {1.2, 2.3999999999999999}, {-1.2, 2.4}}});
    clay.loops.push_back({{{-1.08, 0.22}, {-1.08, 2.3}, {1.0800000000000001, 2.3}, {1.08, 0.22}}});
    SectionLayer odd{"a<b> & \"c\"/d", {0.0, 0.0, 1.0}, {}};
    odd.loops.push_back({{{2.0, 1.0}, {3.0000000000000004, 1.0}, {2.5, 1.0 + 1e-9}}});
    SectionLayer empty{"empty", {1.0, 0.0, 0.0}, {}};
    SectionLayer repeat{"clay", {0.2, 0.9, 0.1}, {}};
    repeat.loops.push_back({{{0.0, 0.5}, {1e-300, 0.5}, {0.0, 0.6}}});
    d.layers = {clay, odd, empty, repeat};
    return d;
}

void requireSameLoops(const std::vector<SectionLoop>& read,
                      const std::vector<SectionLoop>& written) {
    REQUIRE(read.size() == written.size());
    for (size_t l = 0; l < read.size(); ++l) {
        REQUIRE(read[l].points.size() == written[l].points.size());
        for (size_t k = 0; k < read[l].points.size(); ++k) {
            CHECK(read[l].points[k][0] == written[l].points[k][0]);  // exact: shortest round trip
            CHECK(read[l].points[k][1] == written[l].points[k][1]);
        }
        CHECK((signedArea(read[l]) > 0) == (signedArea(written[l]) > 0));
    }
}

}  // namespace

TEST_CASE("sectionSvg reads back to the same loops, layers and colours") {
    const SectionDrawing d = sampleDrawing();
    const SvgRead svg = readSvg(sectionSvg(d, false));
    // The viewBox is the drawing's rectangle with v negated, undone by the one flip.
    CHECK(svg.viewBox == "-1.25 -2.4 4.25 2.3");
    CHECK(svg.transform == "scale(1,-1)");
    REQUIRE(svg.layers.size() == d.layers.size());
    for (size_t l = 0; l < d.layers.size(); ++l) {
        CHECK(svg.layers[l].name == d.layers[l].name);
        CHECK(svg.layers[l].rgb == expectedRgb(d.layers[l].color));
        requireSameLoops(svg.layers[l].loops, d.layers[l].loops);
        CHECK(svg.paths[l].at("fill-rule") == "evenodd");
    }
    // The clay layer's hole stays clockwise inside its counter-clockwise outer boundary.
    CHECK(signedArea(svg.layers[0].loops[0]) > 0);
    CHECK(signedArea(svg.layers[0].loops[1]) < 0);

    SECTION("ids are valid and unique whatever the names") {
        std::vector<std::string> ids;
        for (const Tag& tag : readTags(sectionSvg(d, false)))
            if (tag.name == "g" && tag.attributes.count("id"))
                ids.push_back(tag.attributes.at("id"));
        CHECK(ids == std::vector<std::string>{"clay", "a_b_____c__d", "empty", "clay-2"});
    }
    SECTION("outline: strokes only, the same geometry") {
        const SvgRead outline = readSvg(sectionSvg(d, true));
        REQUIRE(outline.layers.size() == d.layers.size());
        CHECK(outline.paths[0].at("fill") == "none");
        // One pixel of the 1000 the longer side is shown at, in model units.
        CHECK(std::strtod(outline.paths[0].at("stroke-width").c_str(), nullptr) ==
              Approx(4.25 / 1000).epsilon(1e-12));
        CHECK(outline.layers[0].rgb == expectedRgb(d.layers[0].color));
        requireSameLoops(outline.layers[0].loops, d.layers[0].loops);
    }
    SECTION("an empty section is a valid document with the fallback rectangle") {
        const SvgRead empty = readSvg(sectionSvg(SectionDrawing{}, false));
        CHECK(empty.layers.empty());
        CHECK(empty.viewBox == "0 -1 1 1");
    }
    SECTION("a non-finite coordinate is refused, not written") {
        SectionDrawing bad = d;
        bad.layers[0].loops[0].points[1][0] = std::nan("");
        CHECK_THROWS_AS(sectionSvg(bad, false), std::invalid_argument);
    }
}

TEST_CASE("sectionDxf reads back to the same loops, layers and colours") {
    const SectionDrawing d = sampleDrawing();
    const DxfRead dxf = readDxf(sectionDxf(d));
    CHECK(dxf.sections == std::vector<std::string>{"HEADER", "TABLES", "ENTITIES"});
    CHECK(dxf.header.at("$ACADVER") == std::vector<std::string>{"AC1015"});
    CHECK(dxf.header.at("$INSUNITS") == std::vector<std::string>{"0"});
    CHECK(dxf.header.at("$EXTMIN") == std::vector<std::string>{"-1.25", "0.1", "0"});
    CHECK(dxf.header.at("$EXTMAX") == std::vector<std::string>{"3.0000000000000004", "2.4", "0"});
    // The default layer "0" first, then one per section layer, named within DXF's rules.
    REQUIRE(dxf.layers.size() == d.layers.size() + 1);
    CHECK(dxf.layers[0].name == "0");
    const std::vector<std::string> names = {"clay", "a_b_ & _c__d", "empty", "clay-2"};
    for (size_t l = 0; l < d.layers.size(); ++l) {
        const ReadLayer& layer = dxf.layers[l + 1];
        CHECK(layer.name == names[l]);
        CHECK(layer.rgb == expectedRgb(d.layers[l].color));
        requireSameLoops(layer.loops, d.layers[l].loops);
    }
    // The nearest AutoCAD Colour Index: pure blue is index 5; clay's orange-brown is a hue
    // of the 10–249 wheel, not grey.
    CHECK(dxf.layers[2].aci == 5);
    CHECK(dxf.layers[1].aci >= 10);
    CHECK(dxf.layers[1].aci < 250);

    SECTION("an empty section is a valid file") {
        const DxfRead empty = readDxf(sectionDxf(SectionDrawing{}));
        REQUIRE(empty.layers.size() == 1);
        CHECK(empty.layers[0].aci == 7);  // the default layer: white or black by background
        CHECK(empty.sections == std::vector<std::string>{"HEADER", "TABLES", "ENTITIES"});
    }
}
