// Every bad input the issue lists gives a clear error with its exact line and column.
#include "lang/parser.h"
#include "lang_test_util.h"

using namespace kerf;
using kerf::test::compileText;
using kerf::test::requireOneError;

TEST_CASE("diagnostics: undefined names") {
    SECTION("let, with a suggestion") {
        const auto c = compileText("let wall = 1;\nlet a = 2 * wal;");
        REQUIRE(c.sink.errorCount() == 1);
        const Diagnostic& d = c.sink.diagnostics()[0];
        CHECK(d.message == "undefined name 'wal'");
        CHECK(d.hint == "did you mean 'wall'?");
        CHECK(d.loc.line == 2);
        CHECK(d.loc.col == 13);
    }
    SECTION("solid") {
        requireOneError("solid cup = sphere {};\nobject  cupp;", 2, 9, "undefined solid 'cupp'");
        CHECK(compileText("solid cup = sphere {};\nobject cupp;").sink.diagnostics()[0].hint ==
              "did you mean 'cup'?");
    }
    SECTION("material") {
        requireOneError("material clay {}\nobject sphere {} material clai;", 2, 27,
                        "undefined material 'clai'");
    }
    SECTION("x outside an implicit function") {
        requireOneError("let a = x + 1;", 1, 9, "undefined name 'x'");
    }
    SECTION("a solid used as a number") {
        // Solids are values (issue 9): the error is at the operator and names both types.
        requireOneError("solid s = sphere {};\nlet a = s * 2;", 2, 11,
                        "cannot apply '*' to a solid and a number");
    }
    SECTION("unknown function") {
        requireOneError("let a = sinn(1);", 1, 9, "unknown function 'sinn'");
    }
    SECTION("wrong number of arguments") {
        requireOneError("let a = 1 +\n  atan2(1);", 2, 3, "'atan2' takes 2 arguments, got 1");
    }
}

TEST_CASE("diagnostics: solids and properties") {
    SECTION("unknown solid") {
        const auto c = compileText("object spere { radius 1 };");
        REQUIRE(c.sink.errorCount() == 1);
        CHECK(c.sink.diagnostics()[0].message == "unknown solid 'spere'");
        CHECK_THAT(
            c.sink.diagnostics()[0].hint,
            Catch::Matchers::StartsWith("did you mean 'sphere'? The solids are: sphere, box,"));
        CHECK(c.sink.diagnostics()[0].loc.col == 8);
    }
    SECTION("unknown property, with the valid ones as a hint") {
        const auto c = compileText("object sphere {\n  radius 1\n  raduis 2\n};");
        REQUIRE(c.sink.errorCount() == 1);
        const Diagnostic& d = c.sink.diagnostics()[0];
        CHECK(d.message == "unknown property 'raduis' in sphere");
        CHECK(d.hint == "did you mean 'radius'? sphere takes: center, radius");
        CHECK(d.loc.line == 3);
        CHECK(d.loc.col == 3);
    }
    SECTION("missing property, at the block") {
        requireOneError("object   box { min <0, 0, 0> };", 1, 10, "box needs the property 'max'");
    }
    SECTION("number where a vector is expected") {
        requireOneError("object box { min 0 max <1, 1, 1> };", 1, 18,
                        "property 'min' of box expects a vector, got a number");
    }
    SECTION("vector where a number is expected, at the start of the value") {
        requireOneError("object sphere { radius <1, 2, 3> * 2 };", 1, 24,
                        "property 'radius' of sphere expects a number, got a vector");
    }
    SECTION("property given twice") {
        requireOneError("camera { fov 30 eye <0, 0, -1> fov 40 }", 1, 32,
                        "property 'fov' given twice in camera");
    }
    SECTION("a one-word solid kind without its block") {
        requireOneError("object sphere;", 1, 8, "'sphere' needs a block");
    }
    SECTION("empty Boolean") {
        requireOneError("object union { };", 1, 8, "'union' needs at least one solid");
    }
    SECTION("unknown light kind") {
        requireOneError("light spot { at <0, 1, 0> }", 1, 7, "unknown light kind 'spot'");
    }
    SECTION("defined twice") {
        requireOneError("let a = 1;\nlet a = 2;", 2, 5, "let 'a' is already defined");
    }
    SECTION("reserved word as a name") {
        requireOneError("solid sphere = box { min <0,0,0> max <1,1,1> };", 1, 7,
                        "'sphere' is a reserved word");
    }
}

TEST_CASE("diagnostics: cycles") {
    SECTION("a solid that refers to itself directly") {
        requireOneError("solid a = union { sphere {} a };", 1, 29, "solid 'a' refers to itself");
    }
    SECTION("a solid that refers to itself through others") {
        const auto c = compileText(
            "solid a = union { b };\nsolid b = difference { sphere {} c };\nsolid c = a scale 2;");
        REQUIRE(c.sink.errorCount() == 1);
        const Diagnostic& d = c.sink.diagnostics()[0];
        CHECK(d.message == "solid 'a' refers to itself through 'b' → 'c' → 'a'");
        CHECK(d.loc.line == 3);
        CHECK(d.loc.col == 11);
    }
    SECTION("lets that refer to each other") {
        requireOneError("let a = b + 1;\nlet b = 2 * a;", 2, 13,
                        "let 'a' refers to itself through 'b' → 'a'");
    }
}

TEST_CASE("diagnostics: values that are not finite") {
    requireOneError("let a = 1 / 0;", 1, 11, "value is not finite: 1 / 0 = inf");
    requireOneError("object sphere { radius 1e400 };", 1, 24,
                    "value is not finite: 1e400 is too large");
    requireOneError("let a = 2 + sqrt(-1);", 1, 13, "value is not finite: sqrt(-1) = ");
    requireOneError("let a = log(0);", 1, 9, "value is not finite: log(0) = -inf");
    requireOneError("let v = <1, 2, 3> / 0;", 1, 19, "value is not finite");
}

TEST_CASE("diagnostics: degenerate solids") {
    requireOneError("object sphere { radius -1 };", 1, 24,
                    "sphere radius must be positive, got -1");
    requireOneError("object cylinder { from <0,0,0> to <0,1,0> radius 0 };", 1, 50,
                    "cylinder radius must be positive, got 0");
    requireOneError("object cylinder { from <1,2,3> to <1,2,3> };", 1, 8,
                    "cylinder has zero length");
    requireOneError("object cone { from <0,0,0> to <0,1,0> radius1 0 radius2 0 };", 1, 8,
                    "cone with both radii 0 has no volume");
    requireOneError("object cone { from <0,0,0> to <0,1,0> radius1 -2 };", 1, 47,
                    "cone radius1 must not be negative");
    requireOneError("object torus { major 1 minor 0 };", 1, 30,
                    "torus minor radius must be positive");
    requireOneError("object box { min <0, 0, 0> max <1, 0, 1> };", 1, 8, "empty box");
    requireOneError("object halfspace { normal <0, 0, 0> };", 1, 27,
                    "halfspace normal must not be zero");
    requireOneError("object implicit { f x bound box { min <0, 0, 0> max <-1, 1, 1> } };", 1, 29,
                    "empty bound");
    requireOneError("object sphere {} scale <1, 0, 1>;", 1, 24, "scale by zero");
    requireOneError("object sphere {} matrix [1 0 0 0  2 0 0 0  0 0 1 0];", 1, 18,
                    "matrix is singular");
    requireOneError("object sphere {} translate 2;", 1, 28,
                    "translate expects a vector, got a number");
    requireOneError("object implicit { f <x, 0, 0> bound box { min <0,0,0> max <1,1,1> } };", 1, 22,
                    "a vector component must be a number, got a function of x, y, z");
}

TEST_CASE("diagnostics: camera, lights, mist, render") {
    SECTION("up parallel to the view direction, with a hint") {
        const auto c =
            compileText("camera {\n  eye <0, 5, 0>\n  look_at <0, 0, 0>\n  up <0, 2, 0>\n}");
        REQUIRE(c.sink.errorCount() == 1);
        const Diagnostic& d = c.sink.diagnostics()[0];
        CHECK_THAT(d.message, Catch::Matchers::StartsWith(
                                  "camera up <0, 2, 0> is parallel to the view direction"));
        CHECK_THAT(d.hint, Catch::Matchers::Contains("not parallel"));
        CHECK(d.loc.line == 4);
        CHECK(d.loc.col == 6);
    }
    SECTION("default up parallel: reported at the camera") {
        requireOneError("camera { eye <0, -3, 0> }", 1, 1, "is parallel to the view direction");
    }
    SECTION("eye at look_at") {
        requireOneError("camera { eye <1, 1, 1> look_at <1, 1, 1> }", 1, 32,
                        "camera eye and look_at are the same point");
    }
    SECTION("fov outside (0, 180)") {
        requireOneError("camera { fov 180 }", 1, 14, "camera fov must be between 0 and 180");
        requireOneError("camera { fov 0 }", 1, 14, "camera fov must be between 0 and 180");
        requireOneError("camera { fov -30 }", 1, 14, "camera fov must be between 0 and 180");
    }
    SECTION("mist distance") {
        requireOneError("mist { color <1, 1, 1> distance 0 }", 1, 33,
                        "mist distance must be positive");
    }
    SECTION("render settings are positive integers") {
        requireOneError("render { width 0 }", 1, 16,
                        "render width must be an integer from 1 to 32768, got 0");
        requireOneError("render { spp 2.5 }", 1, 14, "render spp must be an integer");
    }
    SECTION("point light without a position") {
        requireOneError("light point { power 3 }", 1, 1, "point light needs the property 'at'");
    }
    SECTION("given twice") {
        requireOneError("render { }\nrender { }", 2, 1, "render given twice");
    }
    SECTION("operand types in the message") {
        requireOneError("background <1, 1, 1> + 0.5;", 1, 22,
                        "cannot apply '+' to a vector and a number");
    }
}

TEST_CASE("diagnostics: lexical errors and binary garbage") {
    requireOneError("let a = 1;\nlet b = 2; /* never\n closed", 2, 12, "unterminated comment");
    requireOneError("include \"abc.kerf;\nlet a = 1;", 1, 9, "unterminated string");
    requireOneError("let a = 1;\nlet b = 2 # 3;", 2, 11, "unexpected character '#'");
    requireOneError("let a = 1;\nlet b = 2 × 3;", 2, 11, "unexpected character '×'");
    requireOneError(std::string("let a = 1;\nlet b\0 = 2;", 22), 2, 6, "NUL byte");
    requireOneError("let a = 1;\n  let b = \xFF\xFE;", 2, 11, "invalid UTF-8 byte 0xFF");
    requireOneError("let a = \"\xC0\xAF\";", 1, 10, "invalid UTF-8 byte 0xC0");  // overlong '/'
    requireOneError("let a = 1;\x01\x02\x03", 1, 11, "control character 0x01");
}

TEST_CASE("diagnostics: syntax errors") {
    requireOneError("let a = 1\nlet b = 2;", 1, 10,
                    "expected ';' after the let statement, found 'let'");
    requireOneError("object sphere { radius * 2 };", 1, 24, "expected an expression, found '*'");
    requireOneError("sphere { radius 1 };", 1, 1, "expected a statement, found 'sphere'");
    requireOneError("let v = <1, 2>;", 1, 14, "expected ',' after the y component of the vector");
    requireOneError("object union { sphere {} ", 1, 25, "expected '}' to close the union");
    requireOneError("camera { fov 35\nlight point { at <1, 1, 1> }", 2, 1,
                    "expected '}' to close the block opened at line 1, found 'light'");
    requireOneError("object union { sphere {}\nobject sphere {};", 2, 1,
                    "expected '}' to close the union opened at line 1, found 'object'");
    requireOneError("object sphere {} material ;", 1, 27,
                    "expected a material name after 'material', found ';'");
}

// Each section expects exactly one diagnostic: a parser that recursed per level would crash
// here, and one that cascaded would report more. (No wall-clock bound: it could only fail on
// a busy machine.)
TEST_CASE("diagnostics: nesting 100,000 levels deep is one error") {
    SECTION("parentheses") {
        const std::string text =
            "let a = " + std::string(100000, '(') + "1" + std::string(100000, ')') + ";";
        requireOneError(text, 1, 9 + kMaxNesting, "nesting too deep");
    }
    SECTION("unary minus") {
        requireOneError("let a = " + std::string(100000, '-') + "1;", 1, 9 + kMaxNesting,
                        "nesting too deep");
    }
    SECTION("solids") {
        std::string text = "object ";
        for (int i = 0; i < 100000; ++i) text += "union { ";
        text += "sphere {}";
        for (int i = 0; i < 100000; ++i) text += " }";
        text += ";";
        requireOneError(text, 1, 8 + 8 * kMaxNesting, "nesting too deep");
    }
    SECTION("a long chain of operators") {
        std::string text = "let a = 1";
        for (int i = 0; i < 100000; ++i) text += "+1";
        text += ";";
        requireOneError(text, 1, 10 + 2 * kMaxExpressionDepth - 2, "expression too deeply nested");
    }
    SECTION("a chain of 100,000 named solids") {
        std::string text;
        for (int i = 0; i < 100000; ++i)
            text += "solid s" + std::to_string(i) + " = s" + std::to_string(i + 1) + ";\n";
        text += "solid s100000 = sphere {};\n";
        const auto c = compileText(text);
        REQUIRE(c.sink.errorCount() == 1);
        CHECK_THAT(c.sink.diagnostics()[0].message, Catch::Matchers::Contains("nested too deeply"));
    }
}

TEST_CASE("diagnostics: several errors in one run, no cascades") {
    const auto c = compileText(R"(let R = 1.2;
let wall = R / 0;
solid body = sphere { radius -R };
object body;
object bodyy;
object box { min <0, 0, 0> };
let broken = 2 # 3;
object sphere { radius broken };
camera { fov 200 }
)");
    INFO(c.sink.format());
    REQUIRE(c.sink.errorCount() == 6);
    const int lines[] = {2, 3, 5, 6, 7, 9};
    for (int i = 0; i < 6; ++i) CHECK(c.sink.diagnostics()[i].loc.line == lines[i]);
    CHECK_FALSE(c.scene.has_value());
}

TEST_CASE("DiagnosticSink::format") {
    SECTION("location, source line, caret under the column, hint") {
        const auto c = compileText("let wall = 1;\nlet a = 2 * wal;", "m.kerf");
        CHECK(c.sink.format() ==
              "m.kerf:2:13: error: undefined name 'wal'\n"
              "let a = 2 * wal;\n"
              "            ^\n"
              "  hint: did you mean 'wall'?\n");
    }
    SECTION("tabs are kept so the caret lines up") {
        const auto c = compileText("let a =\n\t\t1 / 0;", "t.kerf");
        CHECK(c.sink.format() ==
              "t.kerf:2:5: error: value is not finite: 1 / 0 = inf\n"
              "\t\t1 / 0;\n"
              "\t\t  ^\n");
    }
    SECTION("a multi-byte character before the column takes one cell") {
        DiagnosticSink sink;
        auto file = std::make_shared<const std::string>("u.kerf");
        sink.rememberSource(file, std::make_shared<const std::string>("// é\nlet é"));
        sink.error(SourceLoc{file, 2, 5}, "unexpected character 'é'");
        CHECK(sink.format() == "u.kerf:2:5: error: unexpected character 'é'\nlet é\n    ^\n");
    }
    SECTION("no line: just the file") {
        DiagnosticSink sink;
        sink.error(SourceLoc{std::make_shared<const std::string>("gone.kerf"), 0, 0},
                   "cannot read 'gone.kerf'");
        CHECK(sink.format() == "gone.kerf: error: cannot read 'gone.kerf'\n");
        CHECK(sink.errorCount() == 1);
    }
}
