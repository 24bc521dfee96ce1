// The failure path of csg/check.h: one place that formats, reports and aborts.
#include "csg/check.h"

#include <atomic>
#include <cstdio>
#include <cstdlib>

namespace kerf {
namespace {

void printToStderr(const std::string& message) {
    std::fprintf(stderr, "%s\n", message.c_str());
    std::fflush(stderr);
}

std::atomic<CheckFailureHandler> gHandler{&printToStderr};

}  // namespace

CheckFailureHandler setCheckFailureHandler(CheckFailureHandler handler) {
    return gHandler.exchange(handler ? handler : &printToStderr);
}

namespace check_detail {

std::string showFloat(long double v) {
    char text[64];
    std::snprintf(text, sizeof text, "%.17Lg", v);
    return text;
}

std::string showSigned(long long v) { return std::to_string(v); }
std::string showUnsigned(unsigned long long v) { return std::to_string(v); }

std::string showPointer(const void* p) {
    char text[32];
    std::snprintf(text, sizeof text, "%p", p);
    return text;
}

void fail(const char* file, int line, const char* expression, const std::string& operands) {
    std::string message =
        std::string(file) + ":" + std::to_string(line) + ": check failed: " + expression;
    if (!operands.empty()) message += " " + operands;
    gHandler.load()(message);
    std::abort();
}

}  // namespace check_detail
}  // namespace kerf
