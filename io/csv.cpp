/// @file io/csv.cpp
#include "io/csv.h"

#include <cmath>
#include <cstdio>

namespace kerf {
namespace {

std::string joined(const std::vector<std::string>& fields) {
    std::string line;
    for (size_t i = 0; i < fields.size(); ++i)
        line += (i == 0 ? "" : ",") + CsvTable::quote(fields[i]);
    return line;
}

}  // namespace

CsvTable::CsvTable(std::vector<std::string> columns) : mColumns(std::move(columns)) {
    if (mColumns.empty()) throw std::invalid_argument("CsvTable: no columns");
}

std::string CsvTable::header() const { return joined(mColumns); }

void CsvTable::addRow(const std::vector<std::string>& fields) {
    if (fields.size() != mColumns.size())
        throw std::invalid_argument("CsvTable: a row of " + std::to_string(fields.size()) +
                                    " fields in a table of " + std::to_string(mColumns.size()) +
                                    " columns");
    mRows.push_back(joined(fields));
}

std::string CsvTable::text() const {
    std::string csv = header() + "\n";
    for (const std::string& row : mRows) csv += row + "\n";
    return csv;
}

std::string CsvTable::quote(const std::string& field) {
    if (field.find_first_of(",\"\r\n") == std::string::npos) return field;
    std::string quoted = "\"";
    for (char c : field) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

std::string CsvTable::number(const char* pattern, double value) {
    // snprintf follows LC_NUMERIC, which kerf never changes from "C".
    char text[64];
    if (std::isnan(value)) value = std::fabs(value);  // "nan", never glibc's "-nan"
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

}  // namespace kerf
