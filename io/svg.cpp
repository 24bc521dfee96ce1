/// @file io/svg.cpp
/// @brief SVG text, written as it is added.
#include "io/svg.h"

#include "io/number_text.h"

#include <cmath>
#include <cstdio>

namespace kerf {

SvgWriter::SvgWriter(double width, double height) {
    mText = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + number(width) + "\" height=\"" +
            number(height) + "\" viewBox=\"0 0 " + number(width) + " " + number(height) + "\">\n";
}

SvgWriter::SvgWriter(double minX, double minY, double width, double height, double displayWidth,
                     double displayHeight) {
    mText = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + number(displayWidth) +
            "\" height=\"" + number(displayHeight) + "\" viewBox=\"" + exactNumber(minX) + " " +
            exactNumber(minY) + " " + exactNumber(width) + " " + exactNumber(height) + "\">\n";
}

std::string SvgWriter::number(double value) {
    char text[32];
    if (std::isnan(value)) value = std::fabs(value);  // "nan", never glibc's "-nan"
    std::snprintf(text, sizeof text, "%.2f", value);
    return text;
}

std::string SvgWriter::escape(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '&')
            out += "&amp;";
        else if (c == '<')
            out += "&lt;";
        else if (c == '>')
            out += "&gt;";
        else if (c == '"')
            out += "&quot;";
        else
            out += c;
    }
    return out;
}

void SvgWriter::openTag(const std::string& name, const SvgAttributes& attributes) {
    mText += "<" + name;
    for (const SvgAttribute& a : attributes) mText += " " + a.name + "=\"" + escape(a.value) + "\"";
}

void SvgWriter::element(const std::string& name, const SvgAttributes& attributes) {
    openTag(name, attributes);
    mText += "/>\n";
}

void SvgWriter::element(const std::string& name, const SvgAttributes& attributes,
                        const std::string& content) {
    openTag(name, attributes);
    mText += ">" + escape(content) + "</" + name + ">\n";
}

void SvgWriter::beginGroup(const SvgAttributes& attributes) {
    openTag("g", attributes);
    mText += ">\n";
}

void SvgWriter::endGroup() { mText += "</g>\n"; }

void SvgWriter::line(double x1, double y1, double x2, double y2, const SvgAttributes& extra) {
    SvgAttributes attributes = {
        {"x1", number(x1)}, {"y1", number(y1)}, {"x2", number(x2)}, {"y2", number(y2)}};
    attributes.insert(attributes.end(), extra.begin(), extra.end());
    element("line", attributes);
}

void SvgWriter::circle(double cx, double cy, double r, const SvgAttributes& extra) {
    char radius[32];
    std::snprintf(radius, sizeof radius, "%g", std::isnan(r) ? std::fabs(r) : r);
    SvgAttributes attributes = {{"cx", number(cx)}, {"cy", number(cy)}, {"r", radius}};
    attributes.insert(attributes.end(), extra.begin(), extra.end());
    element("circle", attributes);
}

void SvgWriter::text(double x, double y, const std::string& content, const SvgAttributes& extra) {
    SvgAttributes attributes = {{"x", number(x)}, {"y", number(y)}};
    attributes.insert(attributes.end(), extra.begin(), extra.end());
    element("text", attributes, content);
}

void SvgWriter::polyline(const SvgAttributes& attributes,
                         const std::vector<std::pair<double, double>>& points,
                         const std::string& title) {
    openTag("polyline", attributes);
    mText += " points=\"";
    for (const auto& [x, y] : points) mText += number(x) + "," + number(y) + " ";
    mText += "\">";
    if (!title.empty()) mText += "<title>" + escape(title) + "</title>";
    mText += "</polyline>\n";
}

std::string SvgWriter::finish() {
    std::string document = std::move(mText) + "</svg>\n";
    mText.clear();
    return document;
}

}  // namespace kerf
