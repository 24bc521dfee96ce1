/// @file io/number_text.h
/// @brief Numbers for vector files (SVG paths, DXF values): the shortest decimal that reads
/// back to the same double, in the C locale whatever the process's locale.
#pragma once

#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string>

namespace kerf {

/// Appends the shortest text that parses back to exactly `value` ("0.1", "2.5e-07", "1200");
/// -0 is written "0". Throws std::invalid_argument for NaN and infinities, which no SVG or
/// DXF reader accepts, so a bad coordinate is never written silently.
inline void appendExactNumber(std::string& out, double value) {
    if (!std::isfinite(value)) throw std::invalid_argument("a non-finite coordinate");
    if (value == 0.0) {
        out += '0';
        return;
    }
    char text[32];
    const auto result = std::to_chars(text, text + sizeof text, value);
    out.append(text, result.ptr);
}

/// The same as a string of its own.
inline std::string exactNumber(double value) {
    std::string out;
    appendExactNumber(out, value);
    return out;
}

}  // namespace kerf
