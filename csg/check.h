/// @file csg/check.h
/// @brief Invariant checks: KERF_CHECK* always, KERF_DCHECK* in Debug and sanitizer builds.
///
/// A failed check is a bug in kerf, never a user's mistake (those are diagnostics): it prints
/// `file:line: check failed: <expression>` and, for the comparisons, both operands
/// (`KERF_CHECK_LE(a, b)` prints `(3 vs 2)`), then aborts. KERF_DCHECK* are on unless NDEBUG is
/// defined (the Release build defines it; the Debug, sanitizer and fuzz builds do not) or
/// KERF_FORCE_DCHECK is; off, they compile to nothing and do not evaluate their operands, so
/// they cost nothing in Release. Each operand of a comparison is evaluated once.
#pragma once

#include <string>
#include <type_traits>

namespace kerf {

/// @brief What a failed check calls with its message (no trailing newline). The default prints
/// it to stderr; the program aborts when the handler returns. Tests may install one that throws.
using CheckFailureHandler = void (*)(const std::string& message);

/// @brief Installs handler (nullptr: the default) and returns the one it replaces.
CheckFailureHandler setCheckFailureHandler(CheckFailureHandler handler);

#if !defined(NDEBUG) || defined(KERF_FORCE_DCHECK)
inline constexpr bool kDChecksOn = true;
#else
inline constexpr bool kDChecksOn = false;
#endif

namespace check_detail {

[[noreturn]] void fail(const char* file, int line, const char* expression,
                       const std::string& operands);

// Operands as text, without <sstream> in this widely included header: numbers (doubles to 17
// digits, so they round-trip), enums by value, pointers, strings; anything else as "?".
std::string showFloat(long double v);
std::string showSigned(long long v);
std::string showUnsigned(unsigned long long v);
std::string showPointer(const void* p);

template <typename T>
std::string show(const T& v) {
    if constexpr (std::is_floating_point_v<T>) {
        return showFloat(v);
    } else if constexpr (std::is_enum_v<T>) {
        return show(static_cast<std::underlying_type_t<T>>(v));
    } else if constexpr (std::is_integral_v<T> && std::is_signed_v<T>) {
        return showSigned(v);
    } else if constexpr (std::is_integral_v<T>) {
        return showUnsigned(v);
    } else if constexpr (!std::is_pointer_v<T> && std::is_convertible_v<const T&, std::string>) {
        return "\"" + std::string(v) + "\"";
    } else if constexpr (std::is_pointer_v<T> || std::is_null_pointer_v<T>) {
        return showPointer(v);
    } else {
        return "?";
    }
}

template <typename A, typename B>
[[noreturn]] void failOp(const char* file, int line, const char* expression, const A& a,
                         const B& b) {
    fail(file, line, expression, "(" + show(a) + " vs " + show(b) + ")");
}

}  // namespace check_detail
}  // namespace kerf

#define KERF_CHECK(cond) \
    ((cond) ? (void)0 : ::kerf::check_detail::fail(__FILE__, __LINE__, #cond, std::string()))

#define KERF_CHECK_OP_(op, a, b)                                                             \
    do {                                                                                     \
        const auto& kerfCheckA_ = (a);                                                       \
        const auto& kerfCheckB_ = (b);                                                       \
        if (!(kerfCheckA_ op kerfCheckB_))                                                   \
            ::kerf::check_detail::failOp(__FILE__, __LINE__, #a " " #op " " #b, kerfCheckA_, \
                                         kerfCheckB_);                                       \
    } while (0)

#define KERF_CHECK_EQ(a, b) KERF_CHECK_OP_(==, a, b)
#define KERF_CHECK_NE(a, b) KERF_CHECK_OP_(!=, a, b)
#define KERF_CHECK_LT(a, b) KERF_CHECK_OP_(<, a, b)
#define KERF_CHECK_LE(a, b) KERF_CHECK_OP_(<=, a, b)
#define KERF_CHECK_GT(a, b) KERF_CHECK_OP_(>, a, b)
#define KERF_CHECK_GE(a, b) KERF_CHECK_OP_(>=, a, b)

#if !defined(NDEBUG) || defined(KERF_FORCE_DCHECK)
#define KERF_DCHECK(cond) KERF_CHECK(cond)
#define KERF_DCHECK_EQ(a, b) KERF_CHECK_EQ(a, b)
#define KERF_DCHECK_NE(a, b) KERF_CHECK_NE(a, b)
#define KERF_DCHECK_LT(a, b) KERF_CHECK_LT(a, b)
#define KERF_DCHECK_LE(a, b) KERF_CHECK_LE(a, b)
#define KERF_DCHECK_GT(a, b) KERF_CHECK_GT(a, b)
#define KERF_DCHECK_GE(a, b) KERF_CHECK_GE(a, b)
#else
// Still parsed and type-checked, so an off check cannot rot, but never evaluated: `false &&`
// short-circuits and the optimiser drops it (sizeof would refuse a lambda in C++17).
#define KERF_DCHECK(cond) ((void)(false && (cond)))
#define KERF_DCHECK_OP_OFF_(op, a, b) ((void)(false && ((a)op(b))))
#define KERF_DCHECK_EQ(a, b) KERF_DCHECK_OP_OFF_(==, a, b)
#define KERF_DCHECK_NE(a, b) KERF_DCHECK_OP_OFF_(!=, a, b)
#define KERF_DCHECK_LT(a, b) KERF_DCHECK_OP_OFF_(<, a, b)
#define KERF_DCHECK_LE(a, b) KERF_DCHECK_OP_OFF_(<=, a, b)
#define KERF_DCHECK_GT(a, b) KERF_DCHECK_OP_OFF_(>, a, b)
#define KERF_DCHECK_GE(a, b) KERF_DCHECK_OP_OFF_(>=, a, b)
#endif
