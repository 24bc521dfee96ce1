// Issue 9 §1: values and expressions, each checked by its value (printed with echo, whose
// text is the oracle: numbers in %g, lists and vectors written out).
#include "lang_test_util.h"

#include <cmath>
#include <cstdint>
#include <cstring>

using kerf::test::compileText;
using kerf::test::requireOneError;

namespace {

/// The echo lines of a model that must compile without errors.
std::vector<std::string> echoes(const std::string& text) {
    const auto c = compileText(text);
    INFO(c.sink.format());
    REQUIRE(c.scene.has_value());
    std::vector<std::string> out;
    for (const kerf::Diagnostic& d : c.sink.diagnostics())
        if (d.severity == kerf::Severity::Echo) out.push_back(d.message);
    return out;
}

/// What `echo EXPR;` prints.
std::string value(const std::string& expr) {
    const auto lines = echoes("echo " + expr + ";");
    REQUIRE(lines.size() == 1);
    return lines[0];
}

/// An independent splitmix64 (Vigna's published constants) and the 53-bit mapping that
/// docs/language.md promises for random(seed, i).
double referenceRandom(uint64_t seed, uint64_t i) {
    const auto mix = [](uint64_t z) {
        z += 0x9E3779B97F4A7C15ull;
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    };
    return std::ldexp(static_cast<double>(mix(mix(seed) ^ i) >> 11), -53);
}

}  // namespace

TEST_CASE("values: booleans, comparisons and short-circuit logic") {
    CHECK(value("true") == "true");
    CHECK(value("1 < 2, 2 <= 2, 3 > 4, 4 >= 4, 1 == 1, 1 != 1") ==
          "true, true, false, true, true, false");
    CHECK(value("<1, 2, 3> == <1, 2, 3>, \"a\" < \"b\", [1, [2]] == [1, [2]]") ==
          "true, true, true");
    CHECK(value("true and false, true or false, not true") == "false, true, false");
    // Short circuit: the right side would be an error (an index out of range) if evaluated.
    CHECK(value("false and [1][5] == 1, true or [1][5] == 1") == "false, true");
    CHECK(value("1 + 1 == 2 and 2 * 3 > 5") == "true");  // comparisons bind looser than + and *
    CHECK(value("2 > 1 ? \"big\" : \"small\"") == "big");
    CHECK(value("false ? 1 : true ? 2 : 3") == "2");
    CHECK(value("7 % 3, -7 % 3, 7.5 % 2") == "1, 2, 1.5");
}

TEST_CASE("values: strings, lists, indexing and members") {
    CHECK(value("\"ab\" + \"cd\"") == "abcd");
    CHECK(value("[1, \"a\", true, <1, 2, 3>, [2, [3]]]") ==
          "[1, \"a\", true, <1, 2, 3>, [2, [3]]]");
    CHECK(value("[1, 2] + [3]") == "[1, 2, 3]");
    CHECK(value("[10, 20, 30][2], <4, 5, 6>[1], \"xyz\"[0]") == "30, 5, x");
    CHECK(value("[[1, 2], [3, 4]][1][0]") == "3");
    CHECK(value("<4, 5, 6>.x + <4, 5, 6>.z") == "10");
    CHECK(value("len([1, 2, 3]), len(\"four\"), len([])") == "3, 4, 0");
    CHECK(value("str(\"n = \", 3, \", v = \", <1, 0, 0>)") == "n = 3, v = <1, 0, 0>");
}

TEST_CASE("values: ranges include the end when a step lands on it") {
    CHECK(value("0 .. 3") == "[0, 1, 2, 3]");
    CHECK(value("0 .. 1 step 0.25") == "[0, 0.25, 0.5, 0.75, 1]");
    // Each value is a + i·step in doubles, shown exactly: 3 · 0.3 is 0.8999999999999999.
    CHECK(value("0 .. 1 step 0.3") == "[0, 0.3, 0.6, 0.8999999999999999]");
    CHECK(value("3 .. 0 step -1") == "[3, 2, 1, 0]");
    CHECK(value("1 .. 0") == "[]");
    // 0.3 / 0.1 is 2.9999999999999996 in doubles; the end still counts.
    CHECK(value("len(0 .. 0.3 step 0.1)") == "4");
    // Values are a + i·step, not a running sum: the 1000th of 0.1 steps is exactly 100·… as
    // one multiplication gives it.
    const auto lines = echoes("let r = 0 .. 100 step 0.1; echo r[1000] == 1000 * 0.1, len(r);");
    CHECK(lines[0] == "true, 1001");
    CHECK(value("0 .. 2 - 1") == "[0, 1]");  // a range binds looser than arithmetic
}

TEST_CASE("values: comprehensions") {
    CHECK(value("[for i in 0 .. 4: i * i]") == "[0, 1, 4, 9, 16]");
    CHECK(value("[for i in 0 .. 9 if i % 3 == 0: i]") == "[0, 3, 6, 9]");
    CHECK(value("[for v in [<1, 0, 0>, <0, 2, 0>]: length(v)]") == "[1, 2]");
    CHECK(value("[for i in 0 .. 2: [for j in 0 .. i: j]]") == "[[0], [0, 1], [0, 1, 2]]");
    CHECK(value("[for i in 1 .. 0: i]") == "[]");
}

TEST_CASE("values: vector and angle functions") {
    CHECK(value("dot(<1, 2, 3>, <4, 5, 6>)") == "32");
    CHECK(value("cross(<1, 0, 0>, <0, 1, 0>)") == "<0, 0, 1>");
    CHECK(value("length(<3, 4, 0>)") == "5");
    CHECK(value("normalize(<0, 0, 5>)") == "<0, 0, 1>");
    CHECK(value("deg(pi), rad(180) == pi") == "180, true");
}

TEST_CASE("values: random(seed, i) is splitmix64 mapped to 53 bits, the same everywhere") {
    const auto c = compileText(
        "let r = [for i in 0 .. 9999: random(42, i)];\n"
        "echo min(r[0], r[1]) >= 0, max(r[0], r[9999]) < 1, random(42, 7) == random(42, 7);");
    INFO(c.sink.format());
    REQUIRE(c.scene);
    CHECK(c.sink.diagnostics().back().message == "true, true, true");
    const auto bits =
        echoes("let u = random(1, 2); echo u * 9007199254740992 == floor(u * 9007199254740992);");
    CHECK(bits[0] == "true");  // a multiple of 2^-53
    // The stream's mean over 10,000 draws is 1/2 within 4 standard deviations (0.0029 each).
    const auto mean = echoes(
        "let r = [for i in 0 .. 9999: random(7, i)]; let s = [for v in r if v < 0.5: v];"
        "echo abs(len(s) / 10000 - 0.5) < 0.0116;");
    CHECK(mean[0] == "true");
    for (uint64_t i :
         {0ull, 1ull, 1000ull, 123456789ull}) {  // bit for bit: 17 digits round-trip a double
        char literal[64];
        std::snprintf(literal, sizeof literal, "%.17g", referenceRandom(5, i));
        const auto one = echoes("echo random(5, " + std::to_string(i) + ") == " + literal + ";");
        CHECK(one[0] == "true");
    }
}

TEST_CASE("values: errors name the types involved") {
    requireOneError("let a = 1 < \"b\";", 1, 11, "cannot compare a number and a string with '<'");
    requireOneError("let a = 1 and true;", 1, 9, "'and' expects booleans, got a number");
    requireOneError("let a = 1 ? 2 : 3;", 1, 9,
                    "the condition of '?' must be a boolean, got a number");
    requireOneError("let a = [1, 2][2];", 1, 16,
                    "index 2 is out of range for a list of 2 elements");
    requireOneError("let a = 3[0];", 1, 10, "cannot index a number");
    requireOneError("let a = (1).x;", 1, 13, "'.x' needs a vector, got a number");
    requireOneError("let a = \"s\" * 2;", 1, 13, "cannot apply '*' to a string and a number");
    requireOneError("let a = [1] + 2;", 1, 13, "cannot apply '+' to a list and a number");
    requireOneError("let a = len(3);", 1, 13,
                    "'len' expects a list, a string or a vector, got a number");
    requireOneError("let a = 0 .. 1 step 0;", 1, 21,
                    "the step of a range must be a finite number other than 0");
    requireOneError("let a = random(1.5, 0);", 1, 16, "random's seed must be a whole number");
    requireOneError("object sphere { radius [1] };", 1, 24,
                    "property 'radius' of sphere expects a number, got a list");
    requireOneError("let a = 1 < 2 < 3;", 1, 15, "comparisons do not chain");
}

TEST_CASE("values: vectors still close at '>' and compare in parentheses") {
    CHECK(value("<1, 2, 3>") == "<1, 2, 3>");
    CHECK(value("<1, (2 > 1) ? 5 : 6, 3>") == "<1, 5, 3>");
    CHECK(value("<1, 2 < 3 ? 7 : 8, 3>") == "<1, 7, 3>");
}
