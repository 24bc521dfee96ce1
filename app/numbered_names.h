/// @file app/numbered_names.h
/// @brief The pieces of numbered work a farm splits: a range of numbers "A-B" (frames,
/// layers) and file names with a printf-style %0Nd filled with the number. Used by
/// `kerf render --frames` and `kerf slice --layers`.
#pragma once

#include <cstdint>
#include <string>

namespace kerf::app {

/// The largest frame or layer number accepted: nine digits, so a number always fits `%09d`.
constexpr int64_t kMaxSequenceNumber = 999999999;

/// The numbers first to last, both included.
struct NumberRange {
    int64_t first = 0;
    int64_t last = 0;
    int64_t count() const { return last - first + 1; }
    bool contains(int64_t n) const { return first <= n && n <= last; }
};

/// "A-B" or "N" (one number), digits only, A ≤ B ≤ kMaxSequenceNumber. Throws UsageError
/// naming `option` and showing the text otherwise.
NumberRange parseNumberRange(const std::string& text, const std::string& option);

/// "A-B", or "N" for a single number.
std::string formatNumberRange(const NumberRange& range);

/// Checks that `pattern` holds exactly one number conversion, `%d` or `%0Nd` (N from 1 to 9),
/// with `%%` for a literal percent sign; throws UsageError naming `option` otherwise.
void checkNumberPattern(const std::string& pattern, const std::string& option);

/// The pattern (checked by checkNumberPattern) with its conversion replaced by `number`,
/// zero-padded to the width, and `%%` by `%`; as printf would, without calling it.
std::string expandNumberPattern(const std::string& pattern, int64_t number);

}  // namespace kerf::app
