// The syntax tree the parser builds: statements, precedence, solids, modifiers, recovery.
#include "lang/parser.h"

#include <catch2/catch.hpp>

using namespace kerf;

namespace {

Program parseText(const std::string& text, DiagnosticSink& sink) {
    const SourceText source{std::make_shared<const std::string>("p.kerf"),
                            std::make_shared<const std::string>(text)};
    return parse(tokenize(source, sink), sink);
}

/// The expression in fully parenthesised prefix form, e.g. (+ 1 (* 2 3)); numbers as written
/// (the sink holds the text the syntax tree points into).
std::string show(const Expr& e, const DiagnosticSink& sink) {
    const auto arg = [&](size_t i) { return show(e.args()[i], sink); };
    switch (e.kind) {
        case Expr::Kind::Number: return sink.textAt(e.loc, e.count);
        case Expr::Kind::Name: return e.name();
        case Expr::Kind::Negate: return "(neg " + arg(0) + ")";
        case Expr::Kind::Binary: return std::string("(") + e.op + " " + arg(0) + " " + arg(1) + ")";
        case Expr::Kind::Vector: return "<" + arg(0) + " " + arg(1) + " " + arg(2) + ">";
        case Expr::Kind::Call: {
            std::string s = "(" + e.name();
            for (const Expr& a : e.args()) s += " " + show(a, sink);
            return s + ")";
        }
        default: break;
    }
    return "?";
}

std::string showLet(const std::string& expr) {
    DiagnosticSink sink;
    const Program p = parseText("let a = " + expr + ";", sink);
    INFO(sink.format());
    REQUIRE(sink.errorCount() == 0);
    REQUIRE(p.statements.size() == 1);
    return show(*p.statements[0].expr, sink);
}

}  // namespace

TEST_CASE("parse: expressions") {
    SECTION("precedence and associativity") {
        CHECK(showLet("1 + 2 * 3") == "(+ 1 (* 2 3))");
        CHECK(showLet("1 - 2 - 3") == "(- (- 1 2) 3)");
        CHECK(showLet("8 / 4 / 2") == "(/ (/ 8 4) 2)");
        CHECK(showLet("2 ^ 3 ^ 2") == "(^ 2 (^ 3 2))");
        CHECK(showLet("-2 ^ 2") == "(neg (^ 2 2))");
        CHECK(showLet("2 ^ -1") == "(^ 2 (neg 1))");
        CHECK(showLet("a * -b") == "(* a (neg b))");
        CHECK(showLet("(1 + 2) * 3") == "(* (+ 1 2) 3)");
    }
    SECTION("vectors and calls") {
        CHECK(showLet("<1, 2 * R, -3>") == "<1 (* 2 R) (neg 3)>");
        CHECK(showLet("atan2(y, x) + pi") == "(+ (atan2 y x) pi)");
        CHECK(showLet("clamp(a, 0, 1)") == "(clamp a 0 1)");
    }
    SECTION("locations: operator and start of the expression") {
        DiagnosticSink sink;
        const Program p = parseText("let a =\n  R / 10;", sink);
        const Expr& e = *p.statements[0].expr;
        CHECK(sink.locate(e.loc).line == 2);
        CHECK(sink.locate(e.loc).col == 5);
        CHECK(sink.locate(e.start).col == 3);
    }
}

TEST_CASE("parse: statements and solids") {
    DiagnosticSink sink;
    const Program p = parseText(R"(
solid cup = union { body handle translate <1, 0, 0> };
object cup material clay rotate <0, 30, 0> scale 2;
object implicit { f x^2 + y^2 - 1 bound box { min <-1, -1, -1> max <1, 1, 1> } };
material clay { color <1, 0, 0> }
camera { eye <0, 0, -5> fov 40 };
light point { at <1, 2, 3> }
background <0, 0, 0>;
include "other.kerf";
object sphere {} matrix [1 0 0 -1  0 1 0 0  0 0 1 0];
object sphere {} matrix [1, 0, 0, -1, 0, 1, 0, 0, 0, 0, 1, 0];
)",
                                sink);
    INFO(sink.format());
    REQUIRE(sink.errorCount() == 0);
    REQUIRE(p.statements.size() == 10);

    const Statement& cup = p.statements[0];
    CHECK(cup.kind == Statement::Kind::SolidDef);
    CHECK(cup.name == "cup");
    REQUIRE(cup.solid->kind == Solid::Kind::Boolean);
    REQUIRE(cup.solid->children.size() == 2);
    CHECK(cup.solid->children[0].name == "body");
    CHECK(cup.solid->children[1].name == "handle");
    REQUIRE(cup.solid->children[1].modifiers.size() == 1);
    CHECK(cup.solid->children[1].modifiers[0].kind == Modifier::Kind::Translate);

    const Solid& object = *p.statements[1].solid;
    CHECK(object.kind == Solid::Kind::Reference);
    REQUIRE(object.modifiers.size() == 3);
    CHECK(object.modifiers[0].kind == Modifier::Kind::Material);
    CHECK(object.modifiers[0].material == "clay");
    CHECK(object.modifiers[1].kind == Modifier::Kind::Rotate);
    CHECK(object.modifiers[2].kind == Modifier::Kind::Scale);

    const Solid& implicit = *p.statements[2].solid;
    REQUIRE(implicit.properties.size() == 2);
    CHECK(implicit.properties[0].name == "f");
    CHECK(show(*implicit.properties[0].expr, sink) == "(- (+ (^ x 2) (^ y 2)) 1)");
    REQUIRE(implicit.properties[1].solid);
    CHECK(implicit.properties[1].solid->name == "box");

    CHECK(p.statements[3].kind == Statement::Kind::Material);
    CHECK(p.statements[4].kind == Statement::Kind::Camera);
    CHECK(p.statements[5].kind == Statement::Kind::Light);
    CHECK(p.statements[5].name == "point");
    CHECK(p.statements[6].kind == Statement::Kind::Background);
    CHECK(p.statements[7].kind == Statement::Kind::Include);
    CHECK(p.statements[7].name == "other.kerf");

    SECTION("matrix entries separated by blanks or by commas read the same") {
        for (int s : {8, 9}) {
            const Modifier& m = p.statements[s].solid->modifiers.at(0);
            REQUIRE(m.args.size() == 12);
            CHECK(show(m.args[3], sink) == "(neg 1)");
            CHECK(show(m.args[10], sink) == "1");
        }
    }
}

TEST_CASE("parse: recovery reports several errors") {
    DiagnosticSink sink;
    const Program p = parseText(
        "let a = ;\nlet b = 2;\nobject sphere { radius * } ;\nlet c = (1;\nlet d = 4;", sink);
    REQUIRE(sink.errorCount() == 3);
    CHECK(sink.diagnostics()[0].loc.line == 1);
    CHECK(sink.diagnostics()[1].loc.line == 3);
    CHECK(sink.diagnostics()[2].loc.line == 4);
    // The good statements survive; the broken lets keep their names (marked broken).
    std::vector<std::string> names;
    for (const Statement& s : p.statements) names.push_back(s.name + (s.broken ? "!" : ""));
    CHECK(names == std::vector<std::string>{"a!", "b", "c!", "d"});
}
