/// @file render/accuracy_plot.cpp
/// @brief SVG output of the time-against-error plot.
#include "render/accuracy_plot.h"

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
        case TraceMethod::Closed:
            return "";
        case TraceMethod::Interval:
            return "8,4";
        case TraceMethod::SphereTrace:
            return "2,3";
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

std::string num(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", v);
    return text;
}

std::string escapeXml(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '&')
            out += "&amp;";
        else if (c == '<')
            out += "&lt;";
        else if (c == '>')
            out += "&gt;";
        else
            out += c;
    }
    return out;
}

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

std::string axes(const LogRange& x, const LogRange& y, const AccuracyPlotOptions& o) {
    std::string svg = "<g stroke=\"#000\" stroke-width=\"1\">\n";
    svg += "<line x1=\"" + num(kLeft) + "\" y1=\"" + num(kBottom) + "\" x2=\"" + num(kRight) +
           "\" y2=\"" + num(kBottom) + "\"/>\n";
    svg += "<line x1=\"" + num(kLeft) + "\" y1=\"" + num(kTop) + "\" x2=\"" + num(kLeft) +
           "\" y2=\"" + num(kBottom) + "\"/>\n</g>\n";
    svg += "<g font-family=\"sans-serif\" font-size=\"11\" fill=\"#000\">\n";
    // A tick per decade; a label on every decade while they fit, else on every few.
    const int labelStep = std::max(1, (x.hi - x.lo + 11) / 12);
    for (int e = x.lo; e <= x.hi; ++e) {
        const double px = x.place(std::pow(10.0, e), kLeft, kRight);
        svg += "<line x1=\"" + num(px) + "\" y1=\"" + num(kTop) + "\" x2=\"" + num(px) +
               "\" y2=\"" + num(kBottom + 5) + "\" stroke=\"#ddd\"/>\n";
        if (e % labelStep != 0) continue;
        svg += "<text x=\"" + num(px) + "\" y=\"" + num(kBottom + 18) +
               "\" text-anchor=\"middle\">" + decadeLabel(e) + "</text>\n";
    }
    for (int e = y.lo; e <= y.hi; ++e) {
        const double py = y.place(std::pow(10.0, e), kBottom, kTop);
        svg += "<line x1=\"" + num(kLeft - 5) + "\" y1=\"" + num(py) + "\" x2=\"" + num(kRight) +
               "\" y2=\"" + num(py) + "\" stroke=\"#ddd\"/>\n";
        svg += "<text x=\"" + num(kLeft - 8) + "\" y=\"" + num(py + 4) + "\" text-anchor=\"end\">" +
               decadeLabel(e) + "</text>\n";
    }
    const std::string metric = o.useP99 ? "99th-percentile" : "max";
    svg += "<text x=\"" + num(0.5 * (kLeft + kRight)) + "\" y=\"" + num(kBottom + 40) +
           "\" text-anchor=\"middle\" font-size=\"13\">" + metric +
           " relative hit-distance error |t − t_ref| / t_ref (errors of 0 drawn at " +
           decadeLabel(int(std::round(std::log10(o.errorFloor)))) + ")</text>\n";
    svg += "<text x=\"20\" y=\"" + num(0.5 * (kTop + kBottom)) +
           "\" text-anchor=\"middle\" font-size=\"13\" transform=\"rotate(-90 20 " +
           num(0.5 * (kTop + kBottom)) + ")\">time per primary ray (ns, one thread)</text>\n";
    svg += "<text x=\"" + num(kLeft) + "\" y=\"30\" font-size=\"15\">" + escapeXml(o.title) +
           "</text>\n</g>\n";
    return svg;
}

std::string seriesLine(const Series& s, const LogRange& x, const LogRange& y) {
    std::string svg = "<polyline fill=\"none\" stroke=\"" + std::string(kPalette[s.colour]) +
                      "\" stroke-width=\"1.6\"";
    if (*dashFor(s.method)) svg += " stroke-dasharray=\"" + std::string(dashFor(s.method)) + "\"";
    svg += " points=\"";
    std::string marks;
    for (const Point& p : s.points) {
        const double px = x.place(p.error, kLeft, kRight);
        const double py = y.place(p.nsPerRay, kBottom, kTop);
        svg += num(px) + "," + num(py) + " ";
        marks += "<circle cx=\"" + num(px) + "\" cy=\"" + num(py) + "\" r=\"" +
                 (p.isDefault ? "5\" fill=\"none\" stroke-width=\"1.6\" stroke=\""
                              : "2.2\" stroke=\"none\" fill=\"") +
                 kPalette[s.colour] + "\"/>\n";
    }
    svg += "\"><title>" + escapeXml(s.scene) + " · " + traceMethodName(s.method) +
           "</title></polyline>\n";
    return svg + marks;
}

std::string legend(const std::vector<Series>& series) {
    std::string svg = "<g font-family=\"sans-serif\" font-size=\"11\">\n";
    double yy = kTop + 4;
    const double x0 = kRight + 24;
    for (const Series& s : series) {
        svg += "<line x1=\"" + num(x0) + "\" y1=\"" + num(yy) + "\" x2=\"" + num(x0 + 30) +
               "\" y2=\"" + num(yy) + "\" stroke=\"" + kPalette[s.colour] +
               "\" stroke-width=\"1.6\"" +
               (*dashFor(s.method) ? " stroke-dasharray=\"" + std::string(dashFor(s.method)) + "\""
                                   : std::string()) +
               "/>\n";
        svg += "<text x=\"" + num(x0 + 38) + "\" y=\"" + num(yy + 4) + "\">" + escapeXml(s.scene) +
               " · " + traceMethodName(s.method) + "</text>\n";
        yy += 17;
    }
    yy += 8;
    svg += "<circle cx=\"" + num(x0 + 15) + "\" cy=\"" + num(yy) +
           "\" r=\"5\" fill=\"none\" stroke=\"#000\"/>\n<text x=\"" + num(x0 + 38) + "\" y=\"" +
           num(yy + 4) + "\">default tolerance (1/8 pixel)</text>\n";
    svg += "<text x=\"" + num(x0) + "\" y=\"" + num(yy + 24) +
           "\">solid: closed, dashed: interval, dotted: sphere-trace</text>\n";
    return svg + "</g>\n";
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
    std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + num(kWidth) +
                      "\" height=\"" + num(height) + "\" viewBox=\"0 0 " + num(kWidth) + " " +
                      num(height) + "\">\n<rect width=\"100%\" height=\"100%\" fill=\"#fff\"/>\n";
    svg += axes(x, y, options);
    for (const Series& s : series) svg += seriesLine(s, x, y);
    svg += legend(series);
    return svg + "</svg>\n";
}

}  // namespace kerf
