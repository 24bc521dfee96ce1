/// @file app/numbered_names.cpp
#include "app/numbered_names.h"

#include "app/exit_codes.h"

#include <cctype>

namespace kerf::app {

namespace {

/// The whole of `text` as a non-negative integer of at most nine digits, or -1.
int64_t parseCount(const std::string& text) {
    if (text.empty() || text.size() > 9) return -1;
    int64_t n = 0;
    for (char c : text) {
        if (!std::isdigit(static_cast<unsigned char>(c))) return -1;
        n = n * 10 + (c - '0');
    }
    return n;
}

/// One conversion found in a pattern: [begin, end) of its text and its zero-padded width.
struct Conversion {
    size_t begin = 0, end = 0;
    int width = 0;
};

}  // namespace

NumberRange parseNumberRange(const std::string& text, const std::string& option) {
    const std::string usage = option + " expects A-B or N (whole numbers 0 to " +
                              std::to_string(kMaxSequenceNumber) + ", A ≤ B), got '" + text + "'";
    const size_t dash = text.find('-');
    NumberRange range;
    if (dash == std::string::npos) {
        range.first = range.last = parseCount(text);
    } else {
        range.first = parseCount(text.substr(0, dash));
        range.last = parseCount(text.substr(dash + 1));
    }
    if (range.first < 0 || range.last < 0) throw UsageError(usage);
    if (range.first > range.last)
        throw UsageError(option + ": the range " + text +
                         " is empty (the first number is above the last)");
    return range;
}

std::string formatNumberRange(const NumberRange& range) {
    if (range.first == range.last) return std::to_string(range.first);
    return std::to_string(range.first) + "-" + std::to_string(range.last);
}

namespace {

/// The single conversion of a pattern, or a UsageError naming `option`.
Conversion findConversion(const std::string& pattern, const std::string& option) {
    const std::string usage =
        option +
        ": the name needs exactly one %d or %0Nd (N from 1 to 9) for the number, "
        "e.g. out/turntable_%04d.png, and %% for a percent sign; got '" +
        pattern + "'";
    Conversion found;
    int conversions = 0;
    for (size_t i = 0; i < pattern.size(); ++i) {
        if (pattern[i] != '%') continue;
        if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
            ++i;
            continue;
        }
        Conversion c;
        c.begin = i;
        size_t j = i + 1;
        if (j < pattern.size() && pattern[j] == '0') {
            ++j;
            if (j >= pattern.size() || !std::isdigit(static_cast<unsigned char>(pattern[j])) ||
                pattern[j] == '0')
                throw UsageError(usage);
            c.width = pattern[j] - '0';
            ++j;
        }
        if (j >= pattern.size() || pattern[j] != 'd') throw UsageError(usage);
        c.end = j + 1;
        found = c;
        ++conversions;
        i = j;
    }
    if (conversions != 1) throw UsageError(usage);
    return found;
}

/// `text` with each `%%` made `%`.
std::string unescapePercent(const std::string& text) {
    std::string out;
    for (size_t i = 0; i < text.size(); ++i) {
        out += text[i];
        if (text[i] == '%' && i + 1 < text.size() && text[i + 1] == '%') ++i;
    }
    return out;
}

}  // namespace

void checkNumberPattern(const std::string& pattern, const std::string& option) {
    findConversion(pattern, option);
}

std::string expandNumberPattern(const std::string& pattern, int64_t number) {
    const Conversion c = findConversion(pattern, "the name");
    std::string digits = std::to_string(number);
    if (digits.size() < size_t(c.width)) digits.insert(0, size_t(c.width) - digits.size(), '0');
    return unescapePercent(pattern.substr(0, c.begin)) + digits +
           unescapePercent(pattern.substr(c.end));
}

}  // namespace kerf::app
