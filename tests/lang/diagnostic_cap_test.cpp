// Diagnostics are capped in both languages (issue 24): a model with 10,000 errors once printed
// all of them (1 MB of stderr); the first DiagnosticSink::kMaxErrorsShown are printed, then
// one line counting the rest, and errorCount() still counts them all.
#include "lang/compile.h"
#include "lang/diagnostic.h"
#include "lang/openscad_csg.h"

#include <catch2/catch.hpp>

#include <string>

using namespace kerf;

namespace {

size_t countOf(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

void requireCapped(const DiagnosticSink& sink, int errors, const std::string& file) {
    const std::string out = sink.format();
    INFO(out.substr(0, 2000));
    CHECK(sink.errorCount() == errors);
    CHECK(countOf(out, ": error: ") == size_t(DiagnosticSink::kMaxErrorsShown) + 1);
    CHECK(out.find(file + ": error: " + std::to_string(errors - DiagnosticSink::kMaxErrorsShown) +
                   " more errors not shown (the first 20 are)\n") != std::string::npos);
    CHECK(out.size() < 20000);
}

}  // namespace

TEST_CASE("DiagnosticSink: 10,000 kerf errors print 20 and a count") {
    std::string model;
    for (int i = 0; i < 10000; ++i)
        model += "object sphere { radius nowhere" + std::to_string(i) + " }\n";
    DiagnosticSink sink;
    const auto scene = compileString(model, "many.kerf", sink);
    CHECK_FALSE(scene.has_value());
    requireCapped(sink, 10000, "many.kerf");
}

TEST_CASE("DiagnosticSink: 10,000 OpenSCAD errors print 20 and a count") {
    std::string model;
    for (int i = 0; i < 10000; ++i) model += "sphere(r = \"text\");\n";
    DiagnosticSink sink;
    const auto scene = compileOpenScadString(model, "many.csg", sink);
    CHECK_FALSE(scene.has_value());
    requireCapped(sink, 10000, "many.csg");
}

TEST_CASE("DiagnosticSink: 20 errors print all 20 and no count") {
    std::string model;
    for (int i = 0; i < 20; ++i)
        model += "object sphere { radius nowhere" + std::to_string(i) + " }\n";
    DiagnosticSink sink;
    compileString(model, "twenty.kerf", sink);
    const std::string out = sink.format();
    CHECK(sink.errorCount() == 20);
    CHECK(countOf(out, ": error: ") == 20);
    CHECK(out.find("more errors") == std::string::npos);
}
