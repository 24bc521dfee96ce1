// How diagnostics print: long source lines clipped around the column with the caret still
// under the right character; NaN printed as "nan", never "-nan".
#include "lang_test_util.h"

#include "csg/format.h"
#include "lang/lower.h"
#include "lang/source.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

using namespace kerf;
using namespace kerf::test;

namespace {

/// The lines of the formatted diagnostics.
std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);) out.push_back(l);
    return out;
}

/// The number of terminal cells before byte `bytes` of a UTF-8 string (a character is one).
int cells(const std::string& s, size_t bytes) {
    int n = 0;
    for (size_t i = 0; i < bytes && i < s.size(); ++i)
        n += (static_cast<unsigned char>(s[i]) & 0xC0) != 0x80;
    return n;
}

/// Requires the shown source line (second line) to hold `token` exactly above the caret.
void requireCaretUnder(const std::string& formatted, const std::string& token) {
    const auto l = lines(formatted);
    REQUIRE(l.size() >= 3);
    const size_t tokenAt = l[1].find(token);
    REQUIRE(tokenAt != std::string::npos);
    CHECK(cells(l[1], tokenAt) == cells(l[2], l[2].find('^')));
}

}  // namespace

TEST_CASE("a long source line is clipped around the column, the caret under the error") {
    SECTION("a 4 MB line, the error in the middle: ellipses on both sides") {
        // Comments as filler: a 4 MB expression would be too deep.
        const std::string text = "let a = 1 /* " + std::string(2000000, 'x') + " */ + wal /* " +
                                 std::string(2000000, 'x') + " */;\nlet wall = 1;\n";
        const Compiled c = compileText(text);
        REQUIRE(c.sink.errorCount() == 1);
        const std::string f = c.sink.format();
        CHECK(f.size() < 400);
        const auto l = lines(f);
        CHECK(l[1].rfind("\u2026", 0) == 0);
        CHECK(l[1].size() >= 6);
        CHECK(l[1].compare(l[1].size() - 3, 3, "\u2026") == 0);
        requireCaretUnder(f, "wal ");
    }
    SECTION("the error near the start: only the end is clipped") {
        const Compiled c =
            compileText("let a = wal + 1 /* " + std::string(10000, 'x') + " */;\nlet wall = 1;\n");
        const std::string f = c.sink.format();
        const auto l = lines(f);
        CHECK(l[1].rfind("let a = wal + 1", 0) == 0);
        CHECK(l[1].compare(l[1].size() - 3, 3, "\u2026") == 0);
        requireCaretUnder(f, "wal ");
    }
    SECTION("multi-byte characters: the window starts and ends on whole characters") {
        std::string text = "let a = 1 /* ";
        for (int i = 0; i < 500; ++i) text += "\u00e9";  // é, two bytes
        text += " */ + wal /* ";
        for (int i = 0; i < 500; ++i) text += "\u00e9";
        const Compiled c = compileText(text + " */;\nlet wall = 1;\n");
        const std::string f = c.sink.format();
        const auto l = lines(f);
        REQUIRE(l.size() >= 3);
        // Every é is whole: the line holds only whole two-byte characters besides ASCII.
        DiagnosticSink check;
        CHECK(checkSourceText(SourceText{std::make_shared<const std::string>("x"),
                                         std::make_shared<const std::string>(l[1])},
                              check));
        requireCaretUnder(f, "wal ");
    }
    SECTION("a short line is shown whole") {
        const Compiled c = compileText("let a = 2 * wal;\nlet wall = 1;\n");
        CHECK(lines(c.sink.format())[1] == "let a = 2 * wal;");
    }
}

TEST_CASE("NaN prints as nan, never -nan") {
    const double negativeNan = -std::numeric_limits<double>::quiet_NaN();
    REQUIRE(std::signbit(negativeNan));
    CHECK(formatNumber(negativeNan) == "nan");
    CHECK(formatDouble("%.3f s", negativeNan) == "nan s");
    // sqrt(-1) is a NaN with the sign bit set on x86: the message used to say "-nan".
    requireOneError("let a = 2 + sqrt(-1);", 1, 13, "value is not finite: sqrt(-1) = nan");
}
