// Collecting diagnostics and printing them as FILE:LINE:COL, the source line and a caret.
#include "lang/diagnostic.h"

#include <algorithm>

namespace kerf {

void DiagnosticSink::report(Diagnostic d) {
    if (d.severity == Severity::Error && ++mErrorCount > kMaxErrorsShown) return;  // counted only
    if (d.severity == Severity::Warning && ++mWarningCount > kMaxErrorsShown) return;
    mDiagnostics.push_back(std::move(d));
}

void DiagnosticSink::error(const SourceLoc& loc, std::string message, std::string hint) {
    report(Diagnostic{loc, Severity::Error, std::move(message), std::move(hint), {}});
}

void DiagnosticSink::error(SourcePos pos, std::string message, std::string hint) {
    error(locate(pos), std::move(message), std::move(hint));
}

void DiagnosticSink::rememberSource(std::shared_ptr<const std::string> file,
                                    std::shared_ptr<const std::string> text) {
    mSources.emplace_back(std::move(file), std::move(text));
}

uint32_t DiagnosticSink::sourceIndex(const std::shared_ptr<const std::string>& file,
                                     const std::shared_ptr<const std::string>& text) {
    for (size_t i = mSources.size(); i-- > 0;)
        if (mSources[i].first == file && mSources[i].second == text)
            return static_cast<uint32_t>(i);
    rememberSource(file, text);
    return static_cast<uint32_t>(mSources.size() - 1);
}

SourceLoc DiagnosticSink::locate(SourcePos pos) const {
    if (pos.file >= mSources.size()) return SourceLoc{};
    const auto& [file, text] = mSources[pos.file];
    if (mLineStarts.size() < mSources.size()) mLineStarts.resize(mSources.size());
    std::vector<uint32_t>& starts = mLineStarts[pos.file];
    if (starts.empty()) {
        starts.push_back(0);
        if (text)
            for (size_t i = 0; i < text->size(); ++i)
                if ((*text)[i] == '\n') starts.push_back(static_cast<uint32_t>(i + 1));
    }
    // The last line start at or before the offset.
    const auto next = std::upper_bound(starts.begin(), starts.end(), pos.offset);
    const size_t line = static_cast<size_t>(next - starts.begin());
    return SourceLoc{file, static_cast<int>(line),
                     static_cast<int>(pos.offset - starts[line - 1]) + 1};
}

std::string DiagnosticSink::textAt(SourcePos pos, size_t length) const {
    if (pos.file >= mSources.size() || !mSources[pos.file].second) return {};
    const std::string& text = *mSources[pos.file].second;
    return pos.offset < text.size() ? text.substr(pos.offset, length) : std::string();
}

void DiagnosticSink::sortByLocation(size_t from) {
    if (from >= mDiagnostics.size()) return;
    const auto fileRank = [&](const SourceLoc& loc) {
        if (!loc.file) return -1;
        for (size_t i = 0; i < mSources.size(); ++i)
            if (mSources[i].first && *mSources[i].first == *loc.file) return static_cast<int>(i);
        return static_cast<int>(mSources.size());
    };
    std::stable_sort(mDiagnostics.begin() + static_cast<std::ptrdiff_t>(from), mDiagnostics.end(),
                     [&](const Diagnostic& a, const Diagnostic& b) {
                         const int fa = fileRank(a.loc), fb = fileRank(b.loc);
                         if (fa != fb) return fa < fb;
                         if (a.loc.line != b.loc.line) return a.loc.line < b.loc.line;
                         return a.loc.col < b.loc.col;
                     });
}

namespace {

const char* severityName(Severity s) {
    switch (s) {
        case Severity::Error: return "error";
        case Severity::Warning: return "warning";
        case Severity::Note: return "note";
        case Severity::Echo: return "echo";
    }
    return "error";
}

/// The text of line `line` (1-based) without its line break; false if there is no such line.
bool sourceLine(const std::string& text, int line, std::string& out) {
    size_t start = 0;
    for (int l = 1; l < line; ++l) {
        start = text.find('\n', start);
        if (start == std::string::npos) return false;
        ++start;
    }
    if (start > text.size()) return false;
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    out = text.substr(start, end - start);
    if (!out.empty() && out.back() == '\r') out.pop_back();
    return true;
}

/// Spaces up to the column, keeping tabs so the caret lines up under the terminal's tab stops;
/// a multi-byte UTF-8 character takes one cell.
std::string caretLine(const std::string& lineText, int col) {
    std::string caret;
    for (int i = 0; i + 1 < col; ++i) {
        if (i < static_cast<int>(lineText.size())) {
            const unsigned char c = static_cast<unsigned char>(lineText[i]);
            if ((c & 0xC0) == 0x80) continue;  // UTF-8 continuation byte
            caret += c == '\t' ? '\t' : ' ';
        } else {
            caret += ' ';
        }
    }
    return caret + '^';
}

/// Source lines longer than this many bytes are shown clipped around the column…
constexpr size_t kMaxShownLine = 160;
/// …to this many bytes either side of it, each clipped side marked with an ellipsis.
constexpr size_t kShownAround = 60;

bool isContinuation(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

/// A long line cut to a window around byte column `col` (1-based), on UTF-8 character
/// boundaries; `col` becomes the column of the same character in the window. A 4 MB line
/// used to be echoed whole.
std::string clipAround(const std::string& line, int& col) {
    if (line.size() <= kMaxShownLine) return line;
    const size_t at = std::min(static_cast<size_t>(std::max(col, 1) - 1), line.size());
    size_t start = at > kShownAround ? at - kShownAround : 0;
    while (start < at && isContinuation(line[start])) ++start;
    size_t end = std::min(line.size(), at + kShownAround);
    while (end < line.size() && isContinuation(line[end])) ++end;
    const std::string ellipsis = "\u2026";  // one cell wide: caretLine skips its continuation bytes
    std::string shown = start > 0 ? ellipsis : std::string();
    col = static_cast<int>(at - start + shown.size()) + 1;
    shown += line.substr(start, end - start);
    if (end < line.size()) shown += ellipsis;
    return shown;
}

}  // namespace

std::string DiagnosticSink::format(bool withEchoes) const {
    std::string out;
    for (const Diagnostic& d : mDiagnostics) {
        const std::string fileName = d.loc.file ? *d.loc.file : std::string("<input>");
        if (d.severity == Severity::Echo) {
            if (withEchoes)
                out += fileName + ':' + std::to_string(d.loc.line) + ": echo: " + d.message + '\n';
            continue;
        }
        out += fileName;
        if (d.loc.line > 0)
            out += ':' + std::to_string(d.loc.line) + ':' + std::to_string(d.loc.col);
        out += std::string(": ") + severityName(d.severity) + ": " + d.message + '\n';
        if (d.loc.line > 0 && d.loc.file) {
            for (const auto& [file, text] : mSources) {
                if (!file || !text || *file != *d.loc.file) continue;
                std::string lineText;
                if (sourceLine(*text, d.loc.line, lineText)) {
                    int col = d.loc.col;
                    lineText = clipAround(lineText, col);
                    out += lineText + '\n' + caretLine(lineText, col) + '\n';
                }
                break;
            }
        }
        if (!d.hint.empty()) out += "  hint: " + d.hint + '\n';
        for (const std::string& note : d.notes) out += "  note: " + note + '\n';
    }
    return out + untoldCount();
}

std::string DiagnosticSink::untoldCount() const {
    std::string out;
    std::string fileName = "<input>";
    for (const Diagnostic& d : mDiagnostics)
        if (d.severity == Severity::Error && d.loc.file) {
            fileName = *d.loc.file;
            break;
        }
    const auto tell = [&](int count, const char* severity, const char* what) {
        if (count <= kMaxErrorsShown) return;
        out += fileName + ": " + severity + ": " + std::to_string(count - kMaxErrorsShown) +
               " more " + what + " not shown (the first " + std::to_string(kMaxErrorsShown) +
               " are)\n";
    };
    tell(mErrorCount, "error", "errors");
    tell(mWarningCount, "warning", "warnings");
    return out;
}

}  // namespace kerf
