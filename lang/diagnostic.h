/// @file lang/diagnostic.h
/// @brief Diagnostics are values: a location, a severity, a message and an optional hint,
/// collected in a sink so one run can report several.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace kerf {

/// A position in a source file; line and column are 1-based, the column counts bytes.
struct SourceLoc {
    std::shared_ptr<const std::string> file;  ///< the path as the user named it
    int line = 0;
    int col = 0;
};

/// A position as the syntax tree keeps it: a byte offset into a file the DiagnosticSink
/// remembers, 8 bytes where a SourceLoc takes 24 plus a shared count. Line and column are
/// found only when a diagnostic is reported (DiagnosticSink::locate).
struct SourcePos {
    uint32_t offset = 0;
    uint32_t file = kNoFile;  ///< index of the file in the sink; kNoFile for no position
    static constexpr uint32_t kNoFile = ~uint32_t(0);
};

/// Echo: a line a model prints with `echo` (shown as `FILE:LINE: echo: …`, not an error).
enum class Severity { Error, Warning, Note, Echo };

struct Diagnostic {
    SourceLoc loc;
    Severity severity = Severity::Error;
    std::string message;
    std::string hint;  ///< may be empty
    /// Printed after the hint as `note: …`: e.g. the chain of function calls an error is in,
    /// innermost first ("in call to tooth at gear.kerf:30:5").
    std::vector<std::string> notes;
};

/// Collects diagnostics and knows the text of every file read, to print the offending line.
class DiagnosticSink {
public:
    /// Errors (and, apart, warnings) kept and printed; the rest are counted, and format() ends
    /// with one line saying how many more there were (10,000 errors once took 1 MB of stderr).
    static constexpr int kMaxErrorsShown = 20;

    void report(Diagnostic d);
    void error(const SourceLoc& loc, std::string message, std::string hint = {});
    void error(SourcePos pos, std::string message, std::string hint = {});
    void rememberSource(std::shared_ptr<const std::string> file,
                        std::shared_ptr<const std::string> text);

    /// The index SourcePos uses for this file: the one it was remembered under (same name and
    /// text objects), else it is remembered now.
    uint32_t sourceIndex(const std::shared_ptr<const std::string>& file,
                         const std::shared_ptr<const std::string>& text);
    /// The file, line and column of a position (lines are indexed on the first call per file,
    /// so a sink is not for concurrent use, const or not).
    SourceLoc locate(SourcePos pos) const;
    /// `length` bytes of the remembered text at `pos` (a literal's spelling, for messages).
    std::string textAt(SourcePos pos, size_t length) const;

    bool hasErrors() const { return mErrorCount > 0; }
    int errorCount() const { return mErrorCount; }
    const std::vector<Diagnostic>& diagnostics() const { return mDiagnostics; }

    /// Orders the diagnostics from index `from` on by file (in the order the files were
    /// remembered), line and column, keeping the report order among equals.
    void sortByLocation(size_t from = 0);

    /// `FILE:LINE:COL: error: message`, then the source line and a caret under the column,
    /// then `hint: …` where there is one and `note: …` lines; one block per diagnostic.
    /// Echo lines are `FILE:LINE: echo: …` alone, left out when `withEchoes` is false.
    std::string format(bool withEchoes = true) const;

private:
    std::vector<Diagnostic> mDiagnostics;
    std::vector<std::pair<std::shared_ptr<const std::string>, std::shared_ptr<const std::string>>>
        mSources;
    /// Per remembered file, the offsets where its lines start; built by the first locate().
    mutable std::vector<std::vector<uint32_t>> mLineStarts;
    /// The line counting the errors and warnings past kMaxErrorsShown, or "".
    std::string untoldCount() const;

    int mErrorCount = 0;
    int mWarningCount = 0;
};

}  // namespace kerf
