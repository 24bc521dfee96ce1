// Issue 9 §2–§4: for, if, functions, assert, echo, default material, scopes and limits, each
// checked by the scene it builds or the diagnostic it gives (message, line, column, notes).
#include "lang/lexer.h"
#include "lang/lower.h"
#include "lang/parser.h"
#include "lang/source.h"

#include "lang_test_util.h"

#include <variant>

using namespace kerf;
using kerf::test::compileText;
using kerf::test::requireOneError;

namespace {

Scene compiles(const std::string& text) {
    auto c = compileText(text);
    INFO(c.sink.format());
    REQUIRE(c.scene.has_value());
    return std::move(*c.scene);
}

/// The node under transforms and materials.
const Node& core(const NodePtr& n) {
    const Node* p = n.get();
    while (p->kind() == NodeKind::Transform || p->kind() == NodeKind::Material)
        p = p->children()[0].get();
    return *p;
}

Vec3 sphereCenter(const Node& n) {
    REQUIRE(n.kind() == NodeKind::Sphere);
    return std::get<SphereParams>(n.params()).center;
}

int countLeaves(const Node& n) {
    if (n.children().empty()) return 1;
    int c = 0;
    for (const NodePtr& k : n.children()) c += countLeaves(*k);
    return c;
}

struct Limited {
    DiagnosticSink sink;
    std::optional<Scene> scene;
};

/// Compiles with lowered limits (the real ones take too long to reach in a test).
std::unique_ptr<Limited> compileLimited(const std::string& text, EvalLimits limits) {
    auto out = std::make_unique<Limited>();
    const SourceText source{std::make_shared<const std::string>("test.kerf"),
                            std::make_shared<const std::string>(text)};
    out->sink.rememberSource(source.name, source.text);
    TokenStream tokens(source, out->sink);
    Program program = parse(tokens, out->sink);
    out->scene = Lowering(out->sink, limits).lower(program);
    return out;
}

}  // namespace

TEST_CASE("statements: a top-level for makes one object per value, in order") {
    const Scene s =
        compiles("for i in 0 .. 3 { object sphere { center <i, 2 * i, 0> radius 0.25 }; }");
    REQUIRE(s.objects.size() == 4);
    for (int i = 0; i < 4; ++i) CHECK(sphereCenter(core(s.objects[i])) == Vec3(i, 2 * i, 0));
    const Scene l = compiles("for v in [<1, 0, 0>, <0, 5, 0>] { object sphere { center v }; }");
    REQUIRE(l.objects.size() == 2);
    CHECK(sphereCenter(core(l.objects[1])) == Vec3(0, 5, 0));
    CHECK(compiles("for i in 1 .. 0 { object sphere {}; }").objects.empty());
}

TEST_CASE("statements: loops and conditionals inside Boolean bodies") {
    const Scene s = compiles(
        "object union { for i in 0 .. 9 { box { min <0, 0, 0> max <0.5, 0.5, 0.5> } translate <i, "
        "0, 0> } };");
    REQUIRE(s.objects.size() == 1);
    const Node& u = core(s.objects[0]);
    CHECK(u.kind() == NodeKind::Union);
    CHECK(u.children().size() == 10);
    // if / else if / else choose children; nested loops multiply.
    const Scene c = compiles(
        "object union { for i in 0 .. 5 { for j in 0 .. 1 {\n"
        "  if i == 0 { sphere { center <i, j, 0> } }\n"
        "  else if i < 3 { sphere { center <i, j, 1> } sphere { center <i, j, 2> } }\n"
        "  else { }\n"
        "} } };");
    CHECK(core(c.objects[0]).children().size() == 2 * 1 + 2 * 2 * 2);
    // A difference: the first solid made is the body, the rest cut it.
    const Scene d = compiles(
        "object difference { box { min <-2,-2,-2> max <2,2,2> }\n"
        "  for i in [-1, 1] { sphere { center <i, 0, 0> radius 0.5 } } };");
    const Node& diff = core(d.objects[0]);
    CHECK(diff.kind() == NodeKind::Difference);
    CHECK(diff.children().size() == 3);
}

TEST_CASE("statements: empty loops make empty solids") {
    // A union of nothing is empty: an object of it adds nothing.
    CHECK(compiles("object union { for i in 1 .. 0 { sphere {} } };").objects.empty());
    // Empty cutters leave the body; an empty body leaves nothing.
    const Scene d = compiles(
        "object difference { box { min <0,0,0> max <1,1,1> } for i in 1 .. 0 { sphere {} } };");
    REQUIRE(d.objects.size() == 1);
    CHECK(core(d.objects[0]).kind() == NodeKind::Box);
    CHECK(compiles("object difference { union { for i in 1 .. 0 { sphere {} } } sphere {} };")
              .objects.empty());
    CHECK(compiles("object intersection { sphere {} union { for i in 1 .. 0 { sphere {} } } };")
              .objects.empty());
}

TEST_CASE("statements: top-level if, else if, else") {
    const auto pick = [](int n) {
        return compiles("let n = " + std::to_string(n) +
                        ";\nif n < 0 { object sphere { radius 1 }; } else if n == 0 { object "
                        "sphere { radius 2 }; }"
                        " else { object sphere { radius 3 }; object sphere { radius 4 }; }");
    };
    CHECK(std::get<SphereParams>(core(pick(-1).objects[0]).params()).radius == 1);
    CHECK(std::get<SphereParams>(core(pick(0).objects[0]).params()).radius == 2);
    CHECK(pick(5).objects.size() == 2);
    requireOneError("if 1 { object sphere {}; }", 1, 4,
                    "the condition of 'if' must be a boolean, got a number");
}

TEST_CASE("statements: scopes, shadowing and order independence") {
    // Top-level names may still be used before their line; block lets only after theirs.
    const Scene s = compiles(
        "for i in 0 .. 1 { let c = <i * k, 0, 0>; object sphere { center c }; }\nlet k = 10;");
    CHECK(sphereCenter(core(s.objects[1])) == Vec3(10, 0, 0));
    // Solids are values of lets, used before their line like any top-level name.
    const Scene v =
        compiles("object s;\nlet s = sphere { radius r };\nlet r = q * 2;\nlet q = 0.25;");
    CHECK(std::get<SphereParams>(core(v.objects[0]).params()).radius == 0.5);
    requireOneError("let a = b;\nlet b = [a];", 2, 10,
                    "let 'a' refers to itself through 'b' → 'a'");
    // A loop variable shadows a top-level let inside the loop only.
    const Scene sh = compiles(
        "let i = 100;\nfor i in 0 .. 0 { object sphere { center <i, 0, 0> }; }\n"
        "object sphere { center <i, 0, 0> };");
    CHECK(sphereCenter(core(sh.objects[0])) == Vec3(0, 0, 0));
    CHECK(sphereCenter(core(sh.objects[1])) == Vec3(100, 0, 0));
    // A block's let is gone after the block.
    requireOneError("for i in 0 .. 0 { let q = 1; }\nlet a = q;", 2, 9, "undefined name 'q'");
    // A block let is seen only after its line.
    requireOneError("for i in 0 .. 0 { let a = b; let b = 1; }", 1, 27, "undefined name 'b'");
    // Functions see the top level, not their caller's locals (lexical scope).
    requireOneError("fn f() = j;\nfor j in 0 .. 0 { let a = f(); }", 1, 10, "undefined name 'j'");
    // Inner loops shadow outer ones.
    const Scene n = compiles(
        "object union { for i in 0 .. 0 { for i in 5 .. 5 { sphere { center <i, 0, 0> } } } };");
    CHECK(sphereCenter(core(n.objects[0])) == Vec3(5, 0, 0));
}

TEST_CASE("functions: positional, named and default arguments") {
    const Scene s = compiles(
        "fn ball(r, x = 0, y = x + 1) = sphere { center <x, y, 0> radius r };\n"
        "object ball(1);\nobject ball(2, 3);\nobject ball(y = 7, r = 0.5);");
    REQUIRE(s.objects.size() == 3);
    CHECK(std::get<SphereParams>(core(s.objects[0]).params()).center == Vec3(0, 1, 0));
    CHECK(std::get<SphereParams>(core(s.objects[1]).params()).center == Vec3(3, 4, 0));
    const SphereParams third = std::get<SphereParams>(core(s.objects[2]).params());
    CHECK(third.center == Vec3(0, 7, 0));
    CHECK(third.radius == 0.5);
    // Values other than solids; recursion.
    const auto c = compileText(
        "fn fact(n) = n <= 1 ? 1 : n * fact(n - 1);\nfn pair(a, b = \"z\") = [a, b];\n"
        "echo fact(10), pair(1), pair(b = 2, a = 3);");
    REQUIRE(c.scene);
    CHECK(c.sink.diagnostics().back().message == "3628800, [1, \"z\"], [3, 2]");
    requireOneError("fn f(a) = a;\nlet v = f(b = 1);", 2, 11, "'f' has no parameter 'b'");
    requireOneError("fn f(a, b) = a;\nlet v = f(1);", 2, 9, "missing argument 'b' in call to f");
    requireOneError("fn f(a) = a;\nlet v = f(1, 2);", 2, 14, "'f' takes 1 argument, got 2");
    requireOneError("fn f(a) = a;\nlet v = f(a = 1, a = 2);", 2, 18, "argument 'a' given twice");
    requireOneError("fn f(a) = a;\nfn f(b) = b;", 2, 4, "function 'f' is already defined");
    requireOneError("fn sin(a) = a;", 1, 4, "'sin' is a built-in function and cannot be redefined");
}

TEST_CASE("functions: the same call makes one shared subtree") {
    const Scene s = compiles(
        "fn ring(r, n) = union { for i in 0 .. n - 1 {\n"
        "  sphere { center <r * cos(2*pi*i/n), 0, r * sin(2*pi*i/n)> radius 0.1 } } };\n"
        "object ring(2, 12);\nobject ring(2, 12) translate <0, 1, 0>;\nobject ring(2, 13);");
    REQUIRE(s.objects.size() == 3);
    const Node& a = core(s.objects[0]);
    CHECK(a.children().size() == 12);
    CHECK(&a == &core(s.objects[1]));  // built once
    CHECK(&a != &core(s.objects[2]));
    // A recursive Menger sponge: 20^2 boxes, but level 1 is built once.
    const Scene m = compiles(
        "fn menger(level, s = 1) = level == 0 ? box { min <-s, -s, -s> max <s, s, s> } : union {\n"
        "  for i in [-1, 0, 1] { for j in [-1, 0, 1] { for k in [-1, 0, 1] {\n"
        "    if abs(i) + abs(j) + abs(k) > 1 { menger(level - 1, s / 3) translate <i, j, k> * (2 * "
        "s / 3) }\n"
        "  } } } };\nobject menger(2);");
    const Node& top = core(m.objects[0]);
    CHECK(countLeaves(top) == 400);
    REQUIRE(top.children().size() == 20);
    CHECK(&core(top.children()[0]) == &core(top.children()[19]));
}

TEST_CASE("functions: an error inside a call names the call chain") {
    const auto c = compileText(
        "fn tooth(w) = box { min <0, 0, 0> max <w, 1, 1> };\n"
        "fn gear(n) = union { for i in 0 .. n - 1 { tooth(0.5 - i) } };\n"
        "object gear(3);",
        "gear.kerf");
    REQUIRE_FALSE(c.scene);
    REQUIRE(c.sink.errorCount() == 1);
    const Diagnostic& d = c.sink.diagnostics().front();
    CHECK(d.loc.line == 1);
    CHECK(d.loc.col == 15);
    CHECK_THAT(d.message, Catch::Matchers::Contains("empty box"));
    REQUIRE(d.notes.size() == 2);
    CHECK(d.notes[0] == "in call to tooth at gear.kerf:2:44");
    CHECK(d.notes[1] == "in call to gear at gear.kerf:3:8");
    CHECK_THAT(c.sink.format(),
               Catch::Matchers::Contains("  note: in call to tooth at gear.kerf:2:44\n"));
}

TEST_CASE("functions: runaway recursion is an error naming the function and line") {
    const auto c = compileText("let a = 1;\nfn menger(n) = menger(n + 1);\nlet b = menger(0);");
    REQUIRE_FALSE(c.scene);
    REQUIRE(c.sink.errorCount() == 1);
    const Diagnostic& d = c.sink.diagnostics().front();
    CHECK(d.message == "recursion deeper than " + std::to_string(kMaxCallDepth) +
                           " in call to menger at line 2");
    CHECK(d.loc.line == 2);
    CHECK(d.loc.col == 16);
    CHECK(d.notes.size() == 5 + 1 + 3);  // the two ends of the chain and a count between
}

TEST_CASE("statements: assert, echo and default material") {
    requireOneError("let n = 3;\nassert n < 2, \"n must be small, got \" + str(n);", 2, 1,
                    "assertion failed: n must be small, got 3");
    requireOneError("assert false;", 1, 1, "assertion failed");
    CHECK(compileText("assert 1 < 2, \"fine\";").scene.has_value());
    const auto c = compileText("\necho \"n =\", 1 + 1, <1, 2, 3>;", "m.kerf");
    REQUIRE(c.scene);
    CHECK(c.sink.format() == "m.kerf:2: echo: n =, 2, <1, 2, 3>\n");
    CHECK(c.sink.format(false).empty());  // --quiet
    const Scene s = compiles(
        "material red { color <1, 0, 0> }\nmaterial blue { color <0, 0, 1> }\n"
        "object sphere {};\nobject sphere {} material blue;\ndefault material red;");
    REQUIRE(s.objects.size() == 2);
    REQUIRE(s.objects[0]->kind() == NodeKind::Material);
    CHECK(std::get<MaterialParams>(s.objects[0]->params()).material == 1);
    CHECK(std::get<MaterialParams>(s.objects[1]->params()).material == 2);
    requireOneError("default material gren;\nmaterial green {}", 1, 18,
                    "undefined material 'gren'");
}

TEST_CASE("limits: loops, lists, primitives and strings stop with an error") {
    EvalLimits small;
    small.iterations = 1000;
    auto loop = compileLimited("for i in 0 .. 1e12 { }", small);
    REQUIRE_FALSE(loop->scene);
    CHECK_THAT(loop->sink.diagnostics().front().message,
               Catch::Matchers::Contains("more than 1000 loop iterations and function calls"));
    // Calls count too: a recursion that never repeats its arguments.
    small.iterations = 5000;
    auto calls = compileLimited(
        "fn t(n, p) = n <= 0 ? 0 : t(n - 1, 2 * p) + t(n - 1, 2 * p + 1);\nlet a = t(40, 0);",
        small);
    REQUIRE_FALSE(calls->scene);
    CHECK_THAT(calls->sink.diagnostics().front().message,
               Catch::Matchers::Contains("loop iterations and function calls"));
    EvalLimits list;
    list.listLength = 100;
    auto longList = compileLimited("let a = [for i in 0 .. 1000: i];", list);
    REQUIRE_FALSE(longList->scene);
    CHECK_THAT(longList->sink.diagnostics().front().message,
               Catch::Matchers::Contains("list longer than 100 elements"));
    EvalLimits prims;
    prims.primitives = 50;
    auto many =
        compileLimited("object union { for i in 0 .. 99 { sphere { center <i, 0, 0> } } };", prims);
    REQUIRE_FALSE(many->scene);
    CHECK_THAT(many->sink.diagnostics().front().message,
               Catch::Matchers::Contains("more than 50 primitives"));
    CHECK(many->sink.errorCount() == 1);
    // The real limits are the documented numbers.
    CHECK(kMaxPrimitives == 4'000'000);
    CHECK(kMaxNodes == 4'000'000);
    // Placing one shared solid again and again makes a node per placement: the node limit
    // stops it (the primitive limit counts the shared sphere once; issue 24 saw 6 GB in 17 s).
    EvalLimits nodes;
    nodes.nodes = 1000;
    // Materials and Booleans count too (the second model, on its third line).
    for (const auto& [model, line] : std::vector<std::pair<std::string, int>>{
             {"solid s = sphere { radius 0.4 };\n"
              "object union { for k in 0 .. 200000000 { s translate <k, 0, 0> } };",
              2},
             {"material m { color <1, 0, 0> }\nsolid s = sphere { radius 0.4 };\n"
              "object union { for k in 0 .. 2000 { union { s s } material m } };",
              3}}) {
        auto placed = compileLimited(model, nodes);
        REQUIRE_FALSE(placed->scene);
        CHECK_THAT(placed->sink.diagnostics().front().message,
                   Catch::Matchers::Contains("more than 1000 nodes"));
        CHECK(placed->sink.diagnostics().front().loc.line == line);
        CHECK(placed->sink.errorCount() == 1);
    }
    CHECK(kMaxCallDepth == 100);
    // Doubling a string 21 times passes 1 MB.
    const auto s =
        compileText("fn grow(s, n) = n == 0 ? s : grow(s + s, n - 1);\nlet a = grow(\"x\", 21);");
    REQUIRE_FALSE(s.scene);
    CHECK_THAT(s.sink.diagnostics().front().message,
               Catch::Matchers::Contains("string longer than"));
}
