// Depth limits that do not depend on the order of statements: a chain of named solids or
// lets deeper than kMaxNameDepth, or a solid whose compiled tree is deeper than kMaxCsgDepth,
// is one error at the same definition whichever order the definitions are written in; a
// chain at the limit compiles (scene/limits.h).
#include "lang_test_util.h"

#include "scene/limits.h"

#include <algorithm>
#include <functional>

using namespace kerf;
using namespace kerf::test;

namespace {

/// Definitions 0 … n−1 (definition(i) gives the text of one), one per line, in file order
/// or reversed, then `tail`. Returns the text; `lineOf(i)` is then definition i's line.
struct Chain {
    int n;
    bool reversed;
    std::string text;
    int lineOf(int i) const { return reversed ? n - i : i + 1; }
};

Chain chain(int n, bool reversed, const std::function<std::string(int)>& definition,
            const std::string& tail) {
    std::vector<std::string> lines;
    for (int i = 0; i < n; ++i) lines.push_back(definition(i));
    if (reversed) std::reverse(lines.begin(), lines.end());
    Chain c{n, reversed, {}};
    for (const std::string& l : lines) c.text += l + "\n";
    c.text += tail;
    return c;
}

/// s0 is a sphere; s<i> cuts a small sphere from s<i−1>: name level i + 1, tree height i + 1.
std::string differenceLink(int i) {
    if (i == 0) return "solid s0 = sphere {};";
    return "solid s" + std::to_string(i) + " = difference { s" + std::to_string(i - 1) +
           " sphere { radius 0.1 } };";
}

/// Two nested differences per name: tree height 2i + 1, name level i + 1.
std::string doubleDifferenceLink(int i) {
    if (i == 0) return "solid s0 = sphere {};";
    return "solid s" + std::to_string(i) + " = difference { difference { s" +
           std::to_string(i - 1) + " sphere { radius 0.1 } } sphere { radius 0.2 } };";
}

std::string letLink(int i) {
    if (i == 0) return "let a0 = 1;";
    return "let a" + std::to_string(i) + " = a" + std::to_string(i - 1) + " + 1;";
}

/// The column of `needle` in definition i's text.
int columnOf(const std::string& definition, const std::string& needle) {
    return static_cast<int>(definition.find(needle)) + 1;
}

}  // namespace

TEST_CASE("a chain of named solids deeper than kMaxNameDepth is one error, in either order") {
    const int tooDeep = kMaxNameDepth;  // s<kMaxNameDepth> is at level kMaxNameDepth + 1
    for (const bool reversed : {false, true}) {
        INFO("reversed: " << reversed);
        // 10,000 in file order used to pass `check` and overflow the stack when rendered.
        const Chain c = chain(10000, reversed, differenceLink, "object s9999;\n");
        const std::string prev = "s" + std::to_string(tooDeep - 1) + " ";
        requireOneError(c.text, c.lineOf(tooDeep), columnOf(differenceLink(tooDeep), prev),
                        "nested too deeply");
        // At the limit it compiles, and its tree is kMaxNameDepth levels deep.
        const Chain ok = chain(kMaxNameDepth, reversed, differenceLink,
                               "object s" + std::to_string(kMaxNameDepth - 1) + ";\n");
        const Compiled compiled = compileText(ok.text);
        INFO(compiled.sink.format());
        REQUIRE(compiled.scene.has_value());
        CHECK(compiled.scene->objects[0]->depth() == kMaxNameDepth);
    }
}

TEST_CASE("a chain of lets deeper than kMaxNameDepth is one error, in either order") {
    for (const bool reversed : {false, true}) {
        INFO("reversed: " << reversed);
        const Chain c = chain(10000, reversed, letLink, "");
        const std::string prev = "a" + std::to_string(kMaxNameDepth - 1) + " ";
        requireOneError(c.text, c.lineOf(kMaxNameDepth), columnOf(letLink(kMaxNameDepth), prev),
                        "nested too deeply");
        const Chain ok =
            chain(kMaxNameDepth, reversed, letLink,
                  "object sphere { radius a" + std::to_string(kMaxNameDepth - 1) + " };\n");
        const Compiled compiled = compileText(ok.text);
        INFO(compiled.sink.format());
        CHECK(compiled.scene.has_value());
    }
}

TEST_CASE("a compiled tree deeper than kMaxCsgDepth is one error at the solid that exceeds it") {
    SECTION("named solids, two levels each, in either order") {
        // s<i> is 2i + 1 levels deep: s<k> with 2k + 1 > kMaxCsgDepth is the first too deep.
        const int k = kMaxCsgDepth / 2;
        for (const bool reversed : {false, true}) {
            INFO("reversed: " << reversed);
            const Chain c = chain(3000, reversed, doubleDifferenceLink, "object s2999;\n");
            requireOneError(c.text, c.lineOf(k), columnOf(doubleDifferenceLink(k), "difference"),
                            "nested too deeply");
            const Chain ok = chain(k, reversed, doubleDifferenceLink,
                                   "object s" + std::to_string(k - 1) + ";\n");
            const Compiled compiled = compileText(ok.text);
            INFO(compiled.sink.format());
            REQUIRE(compiled.scene.has_value());
            CHECK(compiled.scene->objects[0]->depth() == 2 * (k - 1) + 1);
        }
    }
    SECTION("material modifiers, one level each") {
        std::string text = "material m { color <1, 0, 0> }\nobject sphere {}";
        for (int i = 0; i < 5000; ++i) text += " material m";
        text += ";\n";
        // The sphere is level 1, so the material that makes level kMaxCsgDepth + 1 is the
        // kMaxCsgDepth-th; each " material m" is 11 bytes after the 16 of "object sphere {}".
        requireOneError(text, 2, 16 + 11 * (kMaxCsgDepth - 1) + 2, "nested too deeply");
    }
}
