// house/function-length: fails on any production function whose body is over 80 lines.
//   kerf_function_length <repository> [limit]
//
// What it counts: the lines strictly between a function body's opening and closing brace, blank
// and comment lines too (a body `{` on the signature's line and a `}` alone on the last line: 80
// lines of statements). The signature is not counted; lambdas and local classes count as part of
// the function they are in.
//
//   kerf_function_length --expect <file>
// checks the scanner itself: every function of the file must be found with the length its
// preceding `// expect: NAME LINES` comment gives, and no other (tests/house/scanner_cases.cpp).
//
// How it finds bodies (a brace-matching scanner, not a parser): comments, string and character
// literals (raw strings too) and preprocessor lines are blanked first. A `{` met at namespace or
// class scope opens
//   - a scope to look inside, when the text before it (since the last `;`, `{` or `}`) names
//     `namespace`, `extern`, or `class`/`struct`/`union`/`enum` before any `(`;
//   - a function body, when that text has a `(` and what follows its last `)` is only
//     qualifiers (`const`, `noexcept`, `override`, `final`, `&`, a trailing `-> type`), or it
//     has a constructor's initializer list (a lone `:`) and the brace follows a `)` or `}`;
//   - anything else (an initializer after `=`, a member's `{...}` default, a braced initializer
//     in a constructor's list), which is skipped.
// Known blind spot: a lambda at namespace scope (`auto f = [] {...};`) is not measured.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

const char* const kModules[] = {"csg",    "scene", "io",     "volume",   "mesh", "lang",
                                "render", "slice", "assets", "accuracy", "app"};

/// @brief The text with comments, literals and preprocessor lines replaced by spaces; newlines
/// are kept so offsets keep their line numbers.
std::string blanked(const std::string& in) {
    std::string out = in;
    size_t i = 0;
    const size_t n = in.size();
    auto blank = [&](size_t from, size_t to) {
        for (size_t k = from; k < to && k < n; ++k) {
            if (out[k] != '\n') out[k] = ' ';
        }
    };
    bool lineStart = true;
    while (i < n) {
        const char c = in[i];
        if (lineStart && c == '#') {  // a directive, with its continuation lines
            size_t j = i;
            while (j < n && !(in[j] == '\n' && in[j - 1] != '\\')) ++j;
            blank(i, j);
            i = j;
            continue;
        }
        if (c == '\n') {
            lineStart = true;
            ++i;
            continue;
        }
        if (!std::isspace(static_cast<unsigned char>(c))) lineStart = false;
        if (c == '/' && i + 1 < n && in[i + 1] == '/') {
            size_t j = in.find('\n', i);
            if (j == std::string::npos) j = n;
            blank(i, j);
            i = j;
        } else if (c == '/' && i + 1 < n && in[i + 1] == '*') {
            size_t j = in.find("*/", i + 2);
            j = j == std::string::npos ? n : j + 2;
            blank(i, j);
            i = j;
        } else if (c == 'R' && i + 1 < n && in[i + 1] == '"' &&
                   (i == 0 ||
                    !(std::isalnum(static_cast<unsigned char>(in[i - 1])) || in[i - 1] == '_'))) {
            const size_t open = in.find('(', i + 2);
            const std::string close = ")" + in.substr(i + 2, open - i - 2) + "\"";
            size_t j = in.find(close, open);
            j = j == std::string::npos ? n : j + close.size();
            blank(i + 1, j - 1);
            i = j;
        } else if (c == '"' || (c == '\'' &&
                                !(i > 0 && std::isxdigit(static_cast<unsigned char>(in[i - 1]))))) {
            // A quote after a hex digit is a digit separator (1'000), not a character literal.
            size_t j = i + 1;
            while (j < n && in[j] != c && in[j] != '\n') j += in[j] == '\\' ? 2 : 1;
            blank(i + 1, j);
            i = j + 1;
        } else {
            ++i;
        }
    }
    return out;
}

bool hasWord(const std::string& text, const char* word) {
    const std::regex re(std::string("(^|[^A-Za-z0-9_])") + word + "([^A-Za-z0-9_]|$)");
    return std::regex_search(text, re);
}

/// @brief The head without leading `template <...>` clauses (whose `class` is no class).
std::string withoutTemplate(std::string head) {
    for (;;) {
        const size_t t = head.find_first_not_of(" \t\n");
        if (t == std::string::npos || head.compare(t, 8, "template") != 0) return head;
        size_t j = head.find('<', t);
        if (j == std::string::npos) return head;
        int depth = 0;
        for (; j < head.size(); ++j) {
            if (head[j] == '<') ++depth;
            if (head[j] == '>' && --depth == 0) break;
        }
        head = head.substr(j + 1);
    }
}

enum class Opens { Scope, Function, InitializerInHead, Other };

/// @brief Whether the text before a `{` at namespace or class scope has a constructor's
/// initializer list: a lone `:` at parenthesis depth 0 after a `)`.
bool hasInitializerList(const std::string& head) {
    int depth = 0;
    bool sawParen = false;
    for (size_t k = 0; k < head.size(); ++k) {
        const char c = head[k];
        if (c == '(') ++depth;
        if (c == ')' && --depth == 0) sawParen = true;
        const bool lone = c == ':' && (k + 1 >= head.size() || head[k + 1] != ':') &&
                          (k == 0 || head[k - 1] != ':');
        if (depth == 0 && sawParen && lone) return true;
    }
    return false;
}

Opens classify(const std::string& rawHead) {
    const std::string head = withoutTemplate(rawHead);
    const std::string beforeParen = head.substr(0, head.find('('));
    if (hasWord(beforeParen, "namespace") || hasWord(beforeParen, "extern")) return Opens::Scope;
    for (const char* w : {"class", "struct", "union", "enum"}) {
        if (hasWord(beforeParen, w)) return Opens::Scope;
    }
    if (head.find('(') == std::string::npos) return Opens::Other;
    int depth = 0;
    for (size_t k = 0; k < head.size(); ++k) {  // `=` outside parentheses: an initializer
        if (head[k] == '(') ++depth;
        if (head[k] == ')') --depth;
        if (depth == 0 && head[k] == '=' && !hasWord(head, "operator")) return Opens::Other;
    }
    const size_t last = head.find_last_not_of(" \t\n");
    const char before = head[last];
    if (hasInitializerList(head)) {
        return before == ')' || before == '}' ? Opens::Function : Opens::InitializerInHead;
    }
    const std::string tail = head.substr(head.rfind(')') + 1);
    static const std::regex qualifiers(
        R"(^\s*((const|volatile|noexcept|override|final|mutable|&&|&)\s*)*(->[^{};]*)?\s*$)");
    return std::regex_match(tail, qualifiers) ? Opens::Function : Opens::Other;
}

/// @brief The function's name: the qualified identifier before the head's first `(`.
std::string nameOf(const std::string& head) {
    static const std::regex name(
        R"(((~?[A-Za-z_][A-Za-z0-9_]*::)*(operator\s*\(\)|operator[^(]*|~?[A-Za-z_][A-Za-z0-9_]*))\s*\()");
    std::smatch m;
    const std::string h = withoutTemplate(head);
    return std::regex_search(h, m, name) ? m[1].str() : std::string("?");
}

struct Long {
    std::string where;
    std::string name;
    int lines;
};

/// @brief Every function of one file longer than limit lines.
void scanFile(const fs::path& file, const std::string& rel, int limit, std::vector<Long>& out) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    const std::string text = blanked(buffer.str());
    std::vector<int> lineOf(text.size() + 1, 1);
    for (size_t k = 0; k < text.size(); ++k) lineOf[k + 1] = lineOf[k] + (text[k] == '\n');

    // Matches the brace at `open`; returns the offset of its `}`.
    auto matching = [&](size_t open) {
        int depth = 0;
        for (size_t k = open; k < text.size(); ++k) {
            if (text[k] == '{') ++depth;
            if (text[k] == '}' && --depth == 0) return k;
        }
        return text.size() - 1;
    };
    std::string head;
    for (size_t k = 0; k < text.size(); ++k) {
        const char c = text[k];
        if (c == ';' || c == '}') {
            head.clear();
        } else if (c == '{') {
            const Opens kind = classify(head);
            if (kind == Opens::Scope) {
                head.clear();
                continue;  // look inside: its `}` clears the head like any other
            }
            const size_t close = matching(k);
            if (kind == Opens::Function) {
                const int lines = std::max(0, lineOf[close] - lineOf[k] - 1);
                if (lines > limit) {
                    out.push_back({rel + ":" + std::to_string(lineOf[k]), nameOf(head), lines});
                }
            }
            if (kind == Opens::InitializerInHead) {
                head += "{}";
            } else {
                head.clear();
            }
            k = close;
        } else {
            head += c;
        }
    }
}

}  // namespace

/// @brief The scanner against the `// expect: NAME LINES` comments of one file; 0 when equal.
int selfTest(const fs::path& file) {
    std::ifstream in(file);
    std::string line;
    std::vector<std::string> expected;
    static const std::regex expect(R"(//\s*expect:\s*(\S+)\s+(\d+))");
    std::smatch m;
    while (std::getline(in, line)) {
        if (std::regex_search(line, m, expect)) expected.push_back(m[1].str() + " " + m[2].str());
    }
    std::vector<Long> found;
    scanFile(file, file.filename().string(), -1, found);
    std::vector<std::string> got;
    for (const Long& f : found) got.push_back(f.name + " " + std::to_string(f.lines));
    if (got == expected) {
        std::printf("house/function-length: the scanner finds the %zu functions of %s\n",
                    got.size(), file.c_str());
        return 0;
    }
    std::printf("house/function-length: scanner self-test of %s failed\n", file.c_str());
    for (size_t k = 0; k < std::max(got.size(), expected.size()); ++k) {
        std::printf("  expected %-30s found %s\n", k < expected.size() ? expected[k].c_str() : "-",
                    k < got.size() ? got[k].c_str() : "-");
    }
    return 1;
}

int main(int argc, char** argv) {
    if (argc == 3 && std::string(argv[1]) == "--expect") return selfTest(argv[2]);
    if (argc < 2) {
        std::fprintf(stderr, "usage: kerf_function_length <repository> [limit]\n");
        return 2;
    }
    const fs::path root = argv[1];
    const int limit = argc > 2 ? std::stoi(argv[2]) : 80;
    std::vector<Long> found;
    int files = 0;
    for (const char* module : kModules) {
        if (!fs::is_directory(root / module)) continue;
        std::vector<fs::path> paths;
        for (const auto& entry : fs::recursive_directory_iterator(root / module)) {
            const std::string ext = entry.path().extension().string();
            if (entry.is_regular_file() && (ext == ".cpp" || ext == ".h"))
                paths.push_back(entry.path());
        }
        std::sort(paths.begin(), paths.end());
        for (const fs::path& p : paths) {
            scanFile(p, fs::relative(p, root).string(), limit, found);
            ++files;
        }
    }
    for (const Long& f : found) {
        std::printf("house/function-length: %s: %s is %d lines (limit %d)\n", f.where.c_str(),
                    f.name.c_str(), f.lines, limit);
    }
    std::printf("house/function-length: %d files, %zu functions over %d lines\n", files,
                found.size(), limit);
    return found.empty() ? 0 : 1;
}
