/// @file app/exit_codes.h
/// @brief The process exit codes of `kerf` and the exception that carries a usage error up to
/// main(), the only place that turns outcomes into an exit.
#pragma once

#include <stdexcept>

namespace kerf::app {

constexpr int kExitSuccess = 0;
/// Anything that is not the user's fault: an output that cannot be written, a crash caught.
constexpr int kExitFailure = 1;
/// Bad input or usage: a bad option, an unreadable or invalid model. Always with a diagnostic.
constexpr int kExitUsage = 2;

/// A mistake in the command line; what() is the message printed after `kerf: error: ` and
/// names the option at fault.
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

}  // namespace kerf::app
