/// @file tests/io/svg_csv_test.cpp
/// @brief SvgWriter and CsvTable: exact text for small documents, escaping and quoting, and a
/// row of the wrong width refused.
#include "io/csv.h"
#include "io/svg.h"

#include <catch2/catch.hpp>

using namespace kerf;

TEST_CASE("SvgWriter") {
    SvgWriter svg(100, 50.5);
    svg.element("rect", {{"width", "100%"}, {"fill", "#fff"}});
    svg.beginGroup({{"stroke", "#000"}});
    svg.line(0, 1.005, 2.5, 3, {{"stroke", "#ddd"}});
    svg.endGroup();
    svg.circle(1, 2, 5, {{"fill", "none"}});
    svg.circle(1, 2, 2.2);
    svg.text(10, 20, "a < b & c", {{"text-anchor", "middle"}});
    svg.polyline({{"fill", "none"}}, {{1, 2}, {3.25, 4}}, "sphere · \"closed\"");
    svg.polyline({}, {});
    const std::string expected =
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"100.00\" height=\"50.50\" "
        "viewBox=\"0 0 100.00 50.50\">\n"
        "<rect width=\"100%\" fill=\"#fff\"/>\n"
        "<g stroke=\"#000\">\n"
        "<line x1=\"0.00\" y1=\"1.00\" x2=\"2.50\" y2=\"3.00\" stroke=\"#ddd\"/>\n"
        "</g>\n"
        "<circle cx=\"1.00\" cy=\"2.00\" r=\"5\" fill=\"none\"/>\n"
        "<circle cx=\"1.00\" cy=\"2.00\" r=\"2.2\"/>\n"
        "<text x=\"10.00\" y=\"20.00\" text-anchor=\"middle\">a &lt; b &amp; c</text>\n"
        "<polyline fill=\"none\" points=\"1.00,2.00 3.25,4.00 \">"
        "<title>sphere · &quot;closed&quot;</title></polyline>\n"
        "<polyline points=\"\"></polyline>\n"
        "</svg>\n";
    CHECK(svg.finish() == expected);
    CHECK(SvgWriter::escape("x=\"<&>\"") == "x=&quot;&lt;&amp;&gt;&quot;");
}

TEST_CASE("CsvTable") {
    CsvTable table({"name", "value", "note"});
    CHECK(table.header() == "name,value,note");
    table.addRow({"plain", CsvTable::number("%.6e", 0.125), ""});
    table.addRow({"a,b", CsvTable::number("%.6g", 1e-9), "say \"hi\"\nthere"});
    CHECK(table.rows() == 2);
    CHECK(table.text() ==
          "name,value,note\n"
          "plain,1.250000e-01,\n"
          "\"a,b\",1e-09,\"say \"\"hi\"\"\nthere\"\n");
    CHECK_THROWS_AS(table.addRow({"too", "few"}), std::invalid_argument);
    CHECK_THROWS_AS(table.addRow({"a", "b", "c", "d"}), std::invalid_argument);
    CHECK(table.rows() == 2);
    CHECK_THROWS_AS(CsvTable({}), std::invalid_argument);
}
