// csg/check.h: the message of a failed check (file:line, expression, both operands), that the
// checks evaluate each operand once, and that KERF_DCHECK* vanish where NDEBUG is defined.
#include "csg/check.h"

#include <catch2/catch.hpp>
#include <stdexcept>
#include <string>

namespace kerf {
namespace {

struct CheckFailed : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Throws the message instead of aborting, so a test can read it.
void throwMessage(const std::string& message) { throw CheckFailed(message); }

/// The message a failing statement reports, or "" when it does not fail.
template <class F>
std::string failureOf(F statement) {
    const CheckFailureHandler previous = setCheckFailureHandler(&throwMessage);
    std::string message;
    try {
        statement();
    } catch (const CheckFailed& e) {
        message = e.what();
    }
    setCheckFailureHandler(previous);
    return message;
}

const std::string kFile = __FILE__;

}  // namespace

TEST_CASE("KERF_CHECK reports file:line and the expression") {
    const int line = __LINE__ + 1;
    const std::string message = failureOf([] { KERF_CHECK(1 + 1 == 3); });
    CHECK(message == kFile + ":" + std::to_string(line) + ": check failed: 1 + 1 == 3");
    CHECK(failureOf([] { KERF_CHECK(2 > 1); }).empty());
}

TEST_CASE("KERF_CHECK_LE and friends print both operands") {
    const int a = 3, b = 2;
    const int line = __LINE__ + 1;
    const std::string le = failureOf([&] { KERF_CHECK_LE(a, b); });
    CHECK(le == kFile + ":" + std::to_string(line) + ": check failed: a <= b (3 vs 2)");
    // Doubles to 17 significant digits, so the printed value is the value compared.
    const double x = 0.1, y = -2.5;
    CHECK(failureOf([&] { KERF_CHECK_LT(x, y); }).find("x < y (0.10000000000000001 vs -2.5)") !=
          std::string::npos);
    const size_t n = 7;
    CHECK(failureOf([&] { KERF_CHECK_EQ(n, size_t(8)); }).find("(7 vs 8)") != std::string::npos);
    const std::string s = "abc";
    CHECK(failureOf([&] { KERF_CHECK_NE(s, std::string("abc")); }).find("(\"abc\" vs \"abc\")") !=
          std::string::npos);
    CHECK(failureOf([&] { KERF_CHECK_GE(a, b); }).empty());
    CHECK(failureOf([&] { KERF_CHECK_GT(b, a); }).find("b > a (2 vs 3)") != std::string::npos);
}

TEST_CASE("KERF_CHECK_* evaluate each operand once") {
    int calls = 0;
    const auto next = [&] { return ++calls; };
    KERF_CHECK_LE(next(), 10);
    CHECK(calls == 1);
}

TEST_CASE("KERF_DCHECK is on exactly where NDEBUG is not defined") {
    int evaluated = 0;
    const auto touch = [&] {
        ++evaluated;
        return false;
    };
    const std::string message = failureOf([&] { KERF_DCHECK(touch()); });
    const std::string messageLe = failureOf([&] { KERF_DCHECK_LE(touch() + 2, 1); });
#ifdef NDEBUG
    STATIC_REQUIRE_FALSE(kDChecksOn);
    // Compiled out: the condition is not even evaluated, and nothing fails.
    CHECK(evaluated == 0);
    CHECK(message.empty());
    CHECK(messageLe.empty());
#else
    STATIC_REQUIRE(kDChecksOn);
    CHECK(evaluated == 2);
    CHECK(message.find("check failed: touch()") != std::string::npos);
    CHECK(messageLe.find("(2 vs 1)") != std::string::npos);
#endif
}

}  // namespace kerf
