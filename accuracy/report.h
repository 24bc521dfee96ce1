/// @file accuracy/report.h
/// @brief The benchmark's results as text: a CSV with one row per scene × method × tolerance,
/// and Markdown tables (scenes, the default tolerance, every row).
#pragma once

#include <string>

#include "accuracy/bench.h"

namespace kerf {

/// The CSV header line's column names, in order (without the newline).
std::string accuracyCsvHeader();

/// Header plus one line per row, '\n'-terminated; numbers in C locale, errors in %.6e.
std::string accuracyCsv(const AccuracyBenchResult& result);

/// Markdown: a scene table, a table of the rows at the default tolerance with the
/// interval/closed time ratio, and the full table.
std::string accuracyMarkdown(const AccuracyBenchResult& result);

}  // namespace kerf
