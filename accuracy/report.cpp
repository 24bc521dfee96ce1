/// @file accuracy/report.cpp
/// @brief CSV and Markdown tables of the accuracy benchmark.
#include "accuracy/report.h"

#include "csg/format.h"

#include "io/csv.h"

#include <cstdio>

namespace kerf {
namespace {

std::string format(const char* pattern, double value) { return formatDouble(pattern, value); }

std::string sci(double value) { return format("%.2e", value); }

/// The row of `method` at the default tolerance of `scene`, or nullptr.
const AccuracyRow* defaultRow(const AccuracyBenchResult& result, const std::string& scene,
                              TraceMethod method) {
    for (const AccuracyRow& row : result.rows)
        if (row.scene == scene && row.method == method && row.isDefaultTolerance) return &row;
    return nullptr;
}

std::string markdownRow(const AccuracyRow& row) {
    const AccuracyMeasurement& m = row.m;
    return "| " + row.scene + " | " + traceMethodName(row.method) + " | " +
           format("%.3g", row.tolerance) + (row.isDefaultTolerance ? " (default)" : "") + " | " +
           format("%.1f", m.nsPerRay) + " | " + format("%.1f", m.rootStepsPerRay) + " | " +
           sci(m.maxRelError) + " | " + sci(m.meanRelError) + " | " + sci(m.p99RelError) + " | " +
           sci(m.maxNormalErrorDegrees) + " | " + std::to_string(m.overTolerance) + " | " +
           std::to_string(m.overToleranceNotThin) + " | " + std::to_string(m.hitMissMismatches) +
           " | " + std::to_string(m.mismatchesNotThin) + " | " + std::to_string(m.uncertainRays) +
           " |\n";
}

const char* kRowHeader =
    "| scene | method | tolerance | ns/ray | steps/ray | max rel err | mean rel err | "
    "p99 rel err | max normal err (°) | err > tol | … not thin | hit/miss | … not thin | "
    "uncertain |\n"
    "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";

std::string sceneTable(const AccuracyBenchResult& result) {
    std::string md =
        "| scene | what | rays | default tolerance | reference hits | reference uncertain | "
        "reference time (s) |\n|---|---|---|---:|---:|---:|---:|\n";
    for (const AccuracySceneSummary& s : result.scenes) {
        md += "| " + s.name + " | " + s.description +
              (s.hasClosedForms ? "" : " — no closed form: closed = interval, not repeated") +
              " | " + std::to_string(s.width) + "×" + std::to_string(s.height) + " | " +
              sci(s.defaultTolerance) + " | " + std::to_string(s.referenceHits) + " | " +
              std::to_string(s.referenceUncertain) + " | " + format("%.2f", s.referenceSeconds) +
              " |\n";
    }
    return md;
}

std::string defaultTable(const AccuracyBenchResult& result) {
    std::string md = kRowHeader;
    for (const AccuracyRow& row : result.rows)
        if (row.isDefaultTolerance) md += markdownRow(row);
    md +=
        "\nInterval over closed-form time at the default tolerance:\n\n"
        "| scene | closed ns/ray | interval ns/ray | interval / closed |\n|---|---:|---:|---:|\n";
    for (const AccuracySceneSummary& s : result.scenes) {
        const AccuracyRow* closed = defaultRow(result, s.name, TraceMethod::Closed);
        const AccuracyRow* interval = defaultRow(result, s.name, TraceMethod::Interval);
        if (closed == nullptr || interval == nullptr || closed->m.nsPerRay <= 0) continue;
        md += "| " + s.name + " | " + format("%.1f", closed->m.nsPerRay) + " | " +
              format("%.1f", interval->m.nsPerRay) + " | " +
              format("%.2f", interval->m.nsPerRay / closed->m.nsPerRay) + " |\n";
    }
    return md;
}

}  // namespace

namespace {

std::vector<std::string> csvColumns() {
    return {"scene",
            "method",
            "tolerance",
            "is_default",
            "width",
            "height",
            "rays",
            "runs",
            "median_seconds",
            "ns_per_ray",
            "rays_per_second",
            "root_steps_per_ray",
            "both_hit",
            "max_rel_error",
            "mean_rel_error",
            "p99_rel_error",
            "max_normal_error_deg",
            "over_tolerance",
            "over_tolerance_not_thin",
            "hit_miss_mismatches",
            "mismatches_not_thin",
            "uncertain_rays"};
}

}  // namespace

std::string accuracyCsvHeader() { return CsvTable(csvColumns()).header(); }

std::string accuracyCsv(const AccuracyBenchResult& result) {
    CsvTable table(csvColumns());
    const auto g = [](double v) { return CsvTable::number("%.6g", v); };
    const auto e = [](double v) { return CsvTable::number("%.6e", v); };
    const auto i = [](long long v) { return std::to_string(v); };
    for (const AccuracyRow& row : result.rows) {
        const AccuracyMeasurement& m = row.m;
        table.addRow({row.scene,
                      traceMethodName(row.method),
                      g(row.tolerance),
                      i(row.isDefaultTolerance ? 1 : 0),
                      i(row.width),
                      i(row.height),
                      i(m.rays),
                      i(m.runs),
                      e(m.medianSeconds),
                      g(m.nsPerRay),
                      g(m.raysPerSecond),
                      g(m.rootStepsPerRay),
                      i(m.bothHit),
                      e(m.maxRelError),
                      e(m.meanRelError),
                      e(m.p99RelError),
                      e(m.maxNormalErrorDegrees),
                      i(m.overTolerance),
                      i(m.overToleranceNotThin),
                      i(m.hitMissMismatches),
                      i(m.mismatchesNotThin),
                      i(m.uncertainRays)});
    }
    return table.text();
}

std::string accuracyMarkdown(const AccuracyBenchResult& result) {
    std::string md = "### Scenes\n\n" + sceneTable(result);
    md += "\n### At the default tolerance\n\n" + defaultTable(result);
    md += "\n### Every tolerance\n\n" + std::string(kRowHeader);
    for (const AccuracyRow& row : result.rows) md += markdownRow(row);
    md +=
        "\nTimes are the median of the runs of one single-threaded pass over the primary "
        "rays. Errors are against the extended-precision reference, over rays where both hit; "
        "rays whose reference is uncertain (a tangency within its own precision) are left "
        "out of every error and counted apart.\n";
    return md;
}

}  // namespace kerf
