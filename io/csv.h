/// @file io/csv.h
/// @brief A CSV table built in memory (RFC 4180 quoting, '\n' line ends, numbers in the C
/// locale), then written in one piece (io/text_file.h). Every row has the header's width.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace kerf {

class CsvTable {
public:
    explicit CsvTable(std::vector<std::string> columns);

    const std::vector<std::string>& columns() const { return mColumns; }
    /// The header line without its newline.
    std::string header() const;

    /// Appends a row; throws std::invalid_argument unless it has one field per column.
    void addRow(const std::vector<std::string>& fields);
    size_t rows() const { return mRows.size(); }

    /// Header and rows, each line '\n'-terminated.
    std::string text() const;

    /// A field as written: quoted (with doubled quotes) when it holds a comma, quote or
    /// line break, else as is.
    static std::string quote(const std::string& field);
    /// `value` by a printf pattern for one double ("%.6e"), in the C locale.
    static std::string number(const char* pattern, double value);

private:
    std::vector<std::string> mColumns;
    std::vector<std::string> mRows;  ///< each a complete line without its newline
};

}  // namespace kerf
