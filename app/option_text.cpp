// Option values shared by the commands.
#include "app/option_text.h"

#include "app/exit_codes.h"

#include <cmath>
#include <cstdlib>

namespace kerf::app {

std::optional<double> parseWholeNumber(const std::string& text) {
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size()) return std::nullopt;
    return v;
}

std::optional<Vec3> parseTriple(const std::string& text) {
    Vec3 v;
    const char* p = text.c_str();
    for (int k = 0; k < 3; ++k) {
        if (k > 0 && *p++ != ',') return std::nullopt;
        char* end = nullptr;
        v[k] = std::strtod(p, &end);
        if (end == p || !std::isfinite(v[k])) return std::nullopt;
        p = end;
    }
    if (*p != '\0') return std::nullopt;
    return v;
}

std::optional<std::pair<int, std::string>> parseAxisSpec(const std::string& spec) {
    if (spec.size() < 3 || spec[1] != '=' || spec[0] < 'x' || spec[0] > 'z') return std::nullopt;
    return std::pair{spec[0] - 'x', spec.substr(2)};
}

double numberOption(const std::string& option, const std::string& text) {
    const std::optional<double> v = parseWholeNumber(text);
    if (!v) throw UsageError(option + " must be a number (got '" + text + "')");
    return *v;
}

}  // namespace kerf::app
