/// @file tests/accuracy/quick_run_test.cpp
/// @brief `kerf bench accuracy --quick` end to end: the executable runs every scene, writes its
/// three files, and the CSV's errors against the long-double reference meet the contract:
/// closed forms exact to rounding, interval tracing within the requested tolerance, and no
/// mismatch the tolerance does not explain.
#include <catch2/catch.hpp>
#include <map>
#include <set>
#include <sstream>

#include "accuracy/catalogue.h"
#include "accuracy/report.h"
#include "app/kerf_runner.h"

using namespace kerf;
using namespace kerf::test;

namespace {

/// One CSV row by column name (the harness writes no quoted fields).
using CsvRow = std::map<std::string, std::string>;

std::vector<std::string> splitOn(const std::string& text, char separator) {
    std::vector<std::string> parts;
    std::istringstream in(text);
    for (std::string part; std::getline(in, part, separator);) parts.push_back(part);
    return parts;
}

std::vector<CsvRow> parseCsv(const std::string& text, const std::string& expectedHeader) {
    const std::vector<std::string> lines = splitOn(text, '\n');
    REQUIRE(!lines.empty());
    REQUIRE(lines[0] == expectedHeader);
    const std::vector<std::string> columns = splitOn(lines[0], ',');
    std::vector<CsvRow> rows;
    for (size_t i = 1; i < lines.size(); ++i) {
        const std::vector<std::string> fields = splitOn(lines[i], ',');
        REQUIRE(fields.size() == columns.size());
        CsvRow row;
        for (size_t c = 0; c < columns.size(); ++c) row[columns[c]] = fields[c];
        rows.push_back(row);
    }
    return rows;
}

double number(const CsvRow& row, const std::string& column) { return std::stod(row.at(column)); }
long count(const CsvRow& row, const std::string& column) { return std::stol(row.at(column)); }

/// Closed forms are exact to rounding: far below any tolerance. Observed at most 9e-15 (the
/// full run in docs/accuracy.csv); 1e-13 leaves room for other compilers' rounding.
constexpr double kClosedFormBound = 1e-13;

}  // namespace

TEST_CASE("kerf bench accuracy --quick: the CSV against the reference") {
    TempDir dir;
    const std::string sceneDir = std::string(KERF_SOURCE_DIR) + "/accuracy/scenes";
    const KerfRun run =
        runKerf(dir, {"bench", "accuracy", "--quick", "--out", "out", "--scene-dir", sceneDir});
    INFO("stderr:\n" << run.err);
    REQUIRE(run.exitCode == 0);
    const std::string csv = readFile(dir.file("out/accuracy.csv"));
    CHECK(readFile(dir.file("out/accuracy.svg")).rfind("<svg ", 0) == 0);
    CHECK(readFile(dir.file("out/accuracy_table.md")).find("### Scenes") == 0);
    std::vector<std::string> written;
    for (const auto& entry : fs::directory_iterator(dir.path() / "out"))
        written.push_back(entry.path().filename().string());
    CHECK(written.size() == 3);  // no temporary file left behind

    const std::vector<CsvRow> rows = parseCsv(csv, accuracyCsvHeader());
    // Every scene × method (closed only where closed forms exist) × (1e-3, 1e-9, default).
    size_t expectedRows = 0;
    std::set<std::string> closedScenes;
    for (const AccuracySceneSpec& spec : accuracySceneCatalogue()) {
        expectedRows += (spec.hasClosedForms ? 3 : 2) * 3;
        if (spec.hasClosedForms) closedScenes.insert(spec.name);
    }
    REQUIRE(rows.size() == expectedRows);

    int closedRows = 0, intervalRows = 0;
    for (const CsvRow& row : rows) {
        const std::string& method = row.at("method");
        const double tolerance = number(row, "tolerance");
        INFO(row.at("scene") << " " << method << " tolerance " << tolerance);
        CHECK(count(row, "rays") == count(row, "width") * count(row, "height"));
        if (method == "closed") {
            ++closedRows;
            CHECK(closedScenes.count(row.at("scene")) == 1);
            CHECK(count(row, "both_hit") > 0);
            CHECK(count(row, "hit_miss_mismatches") == 0);
            CHECK(count(row, "over_tolerance") == 0);
            CHECK(number(row, "max_rel_error") <= kClosedFormBound);
        } else if (method == "interval") {
            ++intervalRows;
            // The contract at every tolerance: every error beyond it, and every hit/miss
            // disagreement, is a span thinner than the tolerance that vanished.
            CHECK(count(row, "over_tolerance_not_thin") == 0);
            CHECK(count(row, "mismatches_not_thin") == 0);
            if (tolerance == 1e-9) {
                // Fine enough to resolve every feature of the scenes (the thin shell's wall is
                // 1e-5 of its radius): every hit within the tolerance, no mismatch at all.
                CHECK(count(row, "both_hit") > 0);
                CHECK(count(row, "hit_miss_mismatches") == 0);
                CHECK(number(row, "max_rel_error") <= tolerance);
            }
        }
    }
    CHECK(closedRows == int(closedScenes.size()) * 3);
    CHECK(intervalRows == int(accuracySceneCatalogue().size()) * 3);
}

TEST_CASE("kerf bench accuracy: a missing scene folder is a usage error") {
    TempDir dir;
    const KerfRun run = runKerf(dir, {"bench", "accuracy", "--quick", "--scenes", "sphere",
                                      "--scene-dir", dir.file("nowhere")});
    CHECK(run.exitCode == 2);
    CHECK(run.err.find("--scene-dir") != std::string::npos);
    CHECK(run.err.find("accuracy/scenes") != std::string::npos);
}
