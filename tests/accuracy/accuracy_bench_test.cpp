/// @file tests/accuracy/accuracy_bench_test.cpp
/// @brief The accuracy benchmark (accuracy/): its metrics against hand-made references,
/// and a small run on two of its scenes asserting the accuracy targets and the output formats.
#include "accuracy/bench.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "accuracy/plot.h"
#include "accuracy/report.h"
#include "csg/tree/solids.h"
#include "lang/compile.h"

namespace kerf {
namespace {

AccuracyScene loadBenchScene(const std::string& name) {
    const AccuracySceneSpec* spec = findAccuracyScene(name);
    REQUIRE(spec != nullptr);
    DiagnosticSink sink;
    std::optional<Scene> scene =
        compileFile(std::string(KERF_SOURCE_DIR) + "/accuracy/scenes/" + spec->file, sink);
    REQUIRE(scene);
    return {*spec, std::move(*scene)};
}

const AccuracyRow& findRow(const AccuracyBenchResult& result, const std::string& scene,
                           TraceMethod method, double tolerance) {
    for (const AccuracyRow& row : result.rows)
        if (row.scene == scene && row.method == method && row.tolerance == tolerance) return row;
    FAIL("no row " << scene << " " << traceMethodName(method) << " " << tolerance);
    throw std::logic_error("unreachable");
}

std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

size_t countOf(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

}  // namespace

TEST_CASE("measureAccuracy") {
    // A unit sphere 4 away, rays straight at it: the exact first hit is at t = 3 (normal −z).
    const SceneGeometry geometry({makeSphere(Vec3(0.0), 1.0)});
    std::vector<Ray> rays(4, Ray{Vec3(0, 0, -4), Vec3(0, 0, 1)});
    rays[3].dir = Vec3(0, 1, 0);  // misses
    ReferenceImage reference;
    reference.hits.resize(4);
    for (int i = 0; i < 3; ++i) {
        reference.hits[i].kind = ReferenceHit::Kind::Hit;
        reference.hits[i].normal = Vec3(0, 0, -1);
    }
    reference.hits[0].t = 3.0L;
    reference.hits[1].t = 3.0L * (1 + 1e-6L);  // the trace will be 1e-6/(1+1e-6) off
    reference.hits[1].normal = glm::normalize(Vec3(0, 1e-3, -1));
    reference.hits[2].kind = ReferenceHit::Kind::Uncertain;

    const AccuracyMeasurement m =
        measureAccuracy(geometry, rays, reference, TraceMethod::Closed, 1e-9, 3);
    CHECK(m.rays == 4);
    CHECK(m.runs == 3);
    CHECK(m.bothHit == 2);
    CHECK(m.uncertainRays == 1);
    CHECK(m.overTolerance == 1);         // 1e-6 off at tolerance 1e-9
    CHECK(m.overToleranceNotThin == 1);  // the sphere is 2 thick: nothing vanished there
    CHECK(m.hitMissMismatches == 0);
    const double expected = 1e-6 / (1 + 1e-6);
    CHECK(m.maxRelError == Approx(expected).epsilon(1e-9));
    CHECK(m.p99RelError == Approx(expected).epsilon(1e-9));
    CHECK(m.meanRelError == Approx(expected / 2).epsilon(1e-6));
    CHECK(m.maxNormalErrorDegrees == Approx(std::atan(1e-3) * 180 / M_PI).epsilon(1e-9));
    CHECK(m.nsPerRay > 0);

    SECTION("a hit where the reference misses is a mismatch") {
        reference.hits[0].kind = ReferenceHit::Kind::Miss;
        const AccuracyMeasurement m2 =
            measureAccuracy(geometry, rays, reference, TraceMethod::Closed, 1e-9, 1);
        CHECK(m2.hitMissMismatches == 1);
        CHECK(m2.bothHit == 1);
    }
}

TEST_CASE("runAccuracyBench") {
    std::vector<AccuracyScene> scenes = {loadBenchScene("sphere"), loadBenchScene("thin_shell")};
    AccuracyBenchOptions options;
    options.width = 64;
    options.height = 48;
    options.runs = 1;
    const AccuracyBenchResult result = runAccuracyBench(scenes, options);
    const std::vector<double> decades = accuracyDecadeTolerances();
    REQUIRE(decades.size() == 11);
    // Two scenes × three methods × (11 decades + the default).
    REQUIRE(result.rows.size() == 2 * 3 * 12);
    REQUIRE(result.scenes.size() == 2);
    CHECK(result.scenes[0].defaultTolerance == Approx(0.125 * 2 * std::tan(M_PI / 9) / 48));

    SECTION("closed-form sphere depths are within 1e-12 at every tolerance") {
        for (const AccuracyRow& row : result.rows) {
            if (row.scene != "sphere" || row.method != TraceMethod::Closed) continue;
            INFO("tolerance " << row.tolerance);
            CHECK(row.m.bothHit > 500);
            CHECK(row.m.maxRelError <= 1e-12);
            CHECK(row.m.hitMissMismatches == 0);
        }
    }
    SECTION("interval depths are within the requested tolerance") {
        for (const AccuracyRow& row : result.rows) {
            // The shell's wall is 1e-5 of its radius: at coarser tolerances it may vanish (by
            // contract) and the ray then hits the far wall, so check it only below that.
            const bool wallResolved = row.scene == "sphere" || row.tolerance <= 1e-7;
            if (row.method != TraceMethod::Interval || !wallResolved) continue;
            INFO(row.scene << " tolerance " << row.tolerance);
            CHECK(row.m.bothHit > 500);
            CHECK(row.m.maxRelError <= row.tolerance);
        }
    }
    SECTION("sphere tracing misses the thin shell where interval tracing does not") {
        const AccuracyRow& interval = findRow(result, "thin_shell", TraceMethod::Interval, 1e-9);
        const AccuracyRow& sphereTrace =
            findRow(result, "thin_shell", TraceMethod::SphereTrace, 1e-9);
        CHECK(interval.m.hitMissMismatches == 0);
        CHECK(sphereTrace.m.hitMissMismatches > 0);
        CHECK(sphereTrace.m.mismatchesNotThin > 0);
    }
    SECTION("at the default tolerance the closed-form shell is still found") {
        // The wall is 1e-5 of the radius, thinner than the default tolerance (about 2e-3 at 48
        // rows). Its faces are closed forms, exact to rounding, so the sheet must not vanish:
        // a span goes only when it is within its own boundaries' error.
        const AccuracyRow& row =
            findRow(result, "thin_shell", TraceMethod::Closed, result.scenes[1].defaultTolerance);
        CHECK(row.m.bothHit > 100);
        CHECK(row.m.hitMissMismatches == 0);
        CHECK(row.m.maxRelError <= 1e-12);
    }
    SECTION("the CSV has a row per measurement with every column") {
        const std::vector<std::string> lines = splitLines(accuracyCsv(result));
        REQUIRE(lines.size() == result.rows.size() + 1);
        CHECK(lines[0] == accuracyCsvHeader());
        CHECK(countOf(lines[0], ",") == 21);
        std::map<std::string, int> perSceneMethod;
        for (size_t i = 1; i < lines.size(); ++i) {
            CHECK(countOf(lines[i], ",") == 21);
            perSceneMethod[lines[i].substr(0, lines[i].find(',', lines[i].find(',') + 1))]++;
        }
        CHECK(perSceneMethod["sphere,closed"] == 12);
        CHECK(perSceneMethod["sphere,sphere-trace"] == 12);
        CHECK(perSceneMethod["thin_shell,interval"] == 12);
        CHECK(countOf(accuracyCsv(result), ",1,64,48,") == 6);  // the default rows
    }
    SECTION("the SVG is one document with a polyline per scene and method") {
        const std::string svg = accuracyPlotSvg(result);
        CHECK(svg.rfind("<svg ", 0) == 0);
        CHECK(svg.substr(svg.size() - 7) == "</svg>\n");
        CHECK(countOf(svg, "<polyline") == 6);
        CHECK(countOf(svg, "</polyline>") == 6);
        CHECK(countOf(svg, "<svg") == 1);
    }
    SECTION("the Markdown table has a line per row at the default tolerance") {
        const std::string md = accuracyMarkdown(result);
        CHECK(countOf(md, "(default) |") == 2 * 3 * 2);  // in the default and the full table
    }
}

}  // namespace kerf
