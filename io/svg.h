/// @file io/svg.h
/// @brief A small SVG document writer: elements in the order they are added, attributes in
/// the order given, coordinates with two decimals. Plots (accuracy/), and later sections and
/// contours, draw through it; it knows nothing of what they draw.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace kerf {

/// One attribute: name and value (the value is escaped when written).
struct SvgAttribute {
    std::string name;
    std::string value;
};
using SvgAttributes = std::vector<SvgAttribute>;

class SvgWriter {
public:
    /// Starts a document `width` × `height` user units, with a matching viewBox.
    SvgWriter(double width, double height);
    /// Starts a document whose viewBox is [minX, minX + width] × [minY, minY + height] written
    /// exactly (io/number_text.h), shown `displayWidth` × `displayHeight` (sections in model
    /// units, drawn at a readable size).
    SvgWriter(double minX, double minY, double width, double height, double displayWidth,
              double displayHeight);

    /// A coordinate as written: two decimals, C locale ("12.50").
    static std::string number(double value);
    /// Text made safe for element content and attribute values (&, <, >, ").
    static std::string escape(const std::string& text);

    /// <name a="v" …/>
    void element(const std::string& name, const SvgAttributes& attributes);
    /// <name a="v" …>content</name>, the content escaped.
    void element(const std::string& name, const SvgAttributes& attributes,
                 const std::string& content);

    void beginGroup(const SvgAttributes& attributes);
    void endGroup();

    /// <line x1 y1 x2 y2 …extra/>
    void line(double x1, double y1, double x2, double y2, const SvgAttributes& extra = {});
    /// <circle cx cy r …extra/>; the radius is written short ("5", "2.2").
    void circle(double cx, double cy, double r, const SvgAttributes& extra = {});
    /// <text x y …extra>content</text>
    void text(double x, double y, const std::string& content, const SvgAttributes& extra = {});
    /// <polyline …attributes points="x,y x,y …"><title>title</title></polyline>; no <title>
    /// when `title` is empty.
    void polyline(const SvgAttributes& attributes,
                  const std::vector<std::pair<double, double>>& points,
                  const std::string& title = "");

    /// Closes the document and returns it; the writer is then empty.
    std::string finish();

private:
    void openTag(const std::string& name, const SvgAttributes& attributes);
    std::string mText;
};

}  // namespace kerf
