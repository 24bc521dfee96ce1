/// @file accuracy/plot.cpp
/// @brief The time-against-error plot, drawn through io/svg.h.
#include "accuracy/plot.h"

#include "io/svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace kerf {
namespace {

constexpr double kWidth = 1060, kHeight = 660;
constexpr double kLeft = 90, kTop = 56, kRight = 680, kBottom = 570;  // the plot area

const char* const kPalette[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd",
                                "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};

const char* dashFor(TraceMethod method) {
    switch (method) {
        case TraceMethod::Closed: return "";
        case TraceMethod::Interval: return "8,4";
        case TraceMethod::SphereTrace: return "2,3";
    }
    return "";
}

struct Point {
    double tolerance, error, nsPerRay;
    bool isDefault;
};

struct Series {
    std::string scene;
    TraceMethod method;
    int colour;
    std::vector<Point> points;
};

/// Series in the order their rows appear; colours by scene in order of first appearance.
std::vector<Series> collectSeries(const AccuracyBenchResult& result, const AccuracyPlotOptions& o) {
    std::vector<Series> series;
    std::vector<std::string> scenes;
    for (const AccuracyRow& row : result.rows) {
        auto s = std::find_if(series.begin(), series.end(), [&](const Series& x) {
            return x.scene == row.scene && x.method == row.method;
        });
        if (s == series.end()) {
            auto known = std::find(scenes.begin(), scenes.end(), row.scene);
            if (known == scenes.end()) known = scenes.insert(scenes.end(), row.scene);
            series.push_back({row.scene, row.method, int(known - scenes.begin()) % 8, {}});
            s = series.end() - 1;
        }
        if (row.m.bothHit == 0 || !(row.m.nsPerRay > 0)) continue;  // nothing to place
        const double error = o.useP99 ? row.m.p99RelError : row.m.maxRelError;
        s->points.push_back(
            {row.tolerance, std::max(error, o.errorFloor), row.m.nsPerRay, row.isDefaultTolerance});
    }
    // Along each line the tolerance tightens.
    for (Series& s : series)
        std::sort(s.points.begin(), s.points.end(),
                  [](const Point& a, const Point& b) { return a.tolerance > b.tolerance; });
    return series;
}

/// A decade range [lo, hi] (powers of ten) covering every value; at least one decade wide.
struct LogRange {
    int lo = 0, hi = 1;
    double place(double v, double a, double b) const {  // maps log10(v) from [lo, hi] to [a, b]
        return a + (std::log10(v) - lo) / double(hi - lo) * (b - a);
    }
};

LogRange rangeOf(const std::vector<double>& values) {
    LogRange r;
    if (values.empty()) return r;
    const auto [mn, mx] = std::minmax_element(values.begin(), values.end());
    r.lo = int(std::floor(std::log10(*mn)));
    r.hi = int(std::ceil(std::log10(*mx)));
    if (r.hi <= r.lo) r.hi = r.lo + 1;
    return r;
}

std::string decadeLabel(int e) { return e == 0 ? "1" : "1e" + std::to_string(e); }

std::string num(double v) { return SvgWriter::number(v); }

/// Dash pattern of a method's lines, as an attribute list (none for solid lines).
SvgAttributes dashAttribute(TraceMethod method) {
    if (!*dashFor(method)) return {};
    return {{"stroke-dasharray", dashFor(method)}};
}

void axes(SvgWriter& svg, const LogRange& x, const LogRange& y, const AccuracyPlotOptions& o) {
    svg.beginGroup({{"stroke", "#000"}, {"stroke-width", "1"}});
    svg.line(kLeft, kBottom, kRight, kBottom);
    svg.line(kLeft, kTop, kLeft, kBottom);
    svg.endGroup();
    svg.beginGroup({{"font-family", "sans-serif"}, {"font-size", "11"}, {"fill", "#000"}});
    // A tick per decade; a label on every decade while they fit, else on every few.
    const int labelStep = std::max(1, (x.hi - x.lo + 11) / 12);
    for (int e = x.lo; e <= x.hi; ++e) {
        const double px = x.place(std::pow(10.0, e), kLeft, kRight);
        svg.line(px, kTop, px, kBottom + 5, {{"stroke", "#ddd"}});
        if (e % labelStep != 0) continue;
        svg.text(px, kBottom + 18, decadeLabel(e), {{"text-anchor", "middle"}});
    }
    for (int e = y.lo; e <= y.hi; ++e) {
        const double py = y.place(std::pow(10.0, e), kBottom, kTop);
        svg.line(kLeft - 5, py, kRight, py, {{"stroke", "#ddd"}});
        svg.text(kLeft - 8, py + 4, decadeLabel(e), {{"text-anchor", "end"}});
    }
    const std::string metric = o.useP99 ? "99th-percentile" : "max";
    svg.text(0.5 * (kLeft + kRight), kBottom + 40,
             metric + " relative hit-distance error |t − t_ref| / t_ref (errors of 0 drawn at " +
                 decadeLabel(int(std::round(std::log10(o.errorFloor)))) + ")",
             {{"text-anchor", "middle"}, {"font-size", "13"}});
    const std::string middle = num(0.5 * (kTop + kBottom));
    svg.element("text",
                {{"x", "20"},
                 {"y", middle},
                 {"text-anchor", "middle"},
                 {"font-size", "13"},
                 {"transform", "rotate(-90 20 " + middle + ")"}},
                "time per primary ray (ns, one thread)");
    svg.element("text", {{"x", num(kLeft)}, {"y", "30"}, {"font-size", "15"}}, o.title);
    svg.endGroup();
}

void seriesLine(SvgWriter& svg, const Series& s, const LogRange& x, const LogRange& y) {
    SvgAttributes style = {
        {"fill", "none"}, {"stroke", kPalette[s.colour]}, {"stroke-width", "1.6"}};
    for (const SvgAttribute& a : dashAttribute(s.method)) style.push_back(a);
    std::vector<std::pair<double, double>> points;
    for (const Point& p : s.points)
        points.emplace_back(x.place(p.error, kLeft, kRight), y.place(p.nsPerRay, kBottom, kTop));
    svg.polyline(style, points, s.scene + " · " + traceMethodName(s.method));
    for (size_t k = 0; k < points.size(); ++k) {
        const auto [px, py] = points[k];
        if (s.points[k].isDefault)
            svg.circle(px, py, 5,
                       {{"fill", "none"}, {"stroke-width", "1.6"}, {"stroke", kPalette[s.colour]}});
        else
            svg.circle(px, py, 2.2, {{"stroke", "none"}, {"fill", kPalette[s.colour]}});
    }
}

void legend(SvgWriter& svg, const std::vector<Series>& series) {
    svg.beginGroup({{"font-family", "sans-serif"}, {"font-size", "11"}});
    double yy = kTop + 4;
    const double x0 = kRight + 24;
    for (const Series& s : series) {
        SvgAttributes style = {{"stroke", kPalette[s.colour]}, {"stroke-width", "1.6"}};
        for (const SvgAttribute& a : dashAttribute(s.method)) style.push_back(a);
        svg.line(x0, yy, x0 + 30, yy, style);
        svg.text(x0 + 38, yy + 4, s.scene + " · " + traceMethodName(s.method));
        yy += 17;
    }
    yy += 8;
    svg.circle(x0 + 15, yy, 5, {{"fill", "none"}, {"stroke", "#000"}});
    svg.text(x0 + 38, yy + 4, "default tolerance (1/8 pixel)");
    svg.text(x0, yy + 24, "solid: closed, dashed: interval, dotted: sphere-trace");
    svg.endGroup();
}

}  // namespace

std::string accuracyPlotSvg(const AccuracyBenchResult& result, const AccuracyPlotOptions& options) {
    const std::vector<Series> series = collectSeries(result, options);
    std::vector<double> errors, times;
    for (const Series& s : series)
        for (const Point& p : s.points) {
            errors.push_back(p.error);
            times.push_back(p.nsPerRay);
        }
    const LogRange x = rangeOf(errors);
    const LogRange y = rangeOf(times);
    const double height = std::max(kHeight, kTop + 17.0 * double(series.size()) + 60);
    SvgWriter svg(kWidth, height);
    svg.element("rect", {{"width", "100%"}, {"height", "100%"}, {"fill", "#fff"}});
    axes(svg, x, y, options);
    for (const Series& s : series) seriesLine(svg, s, x, y);
    legend(svg, series);
    return svg.finish();
}

}  // namespace kerf
