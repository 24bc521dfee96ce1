// The .csg reader's tokenizer and parser: module instantiations with named or positional
// literal arguments, nested blocks, OpenSCAD's modifier characters and comments. Nothing is
// evaluated: a .csg file holds no expressions beyond a sign before a number.
#include "lang/openscad_csg.h"
#include "scene/limits.h"

#include <cctype>
#include <cmath>
#include <cstdlib>

namespace kerf {

const ScadArg* ScadCall::arg(const std::string& wanted, int position) const {
    for (const ScadArg& a : args)
        if (a.name == wanted) return &a;
    int index = 0;
    for (const ScadArg& a : args) {
        if (!a.name.empty()) continue;
        if (index++ == position) return &a;
    }
    return nullptr;
}

namespace {

struct ScadToken {
    enum class Kind { End, Name, Number, String, Punct, Bad };
    Kind kind = Kind::End;
    std::string text;  ///< the name, the string's value, or the punctuation character
    double number = 0.0;
    uint32_t offset = 0;
};

class Parser {
public:
    Parser(const std::string& text, uint32_t file, DiagnosticSink& sink)
        : mText(text), mFile(file), mSink(sink) {
        advance();
    }

    std::vector<ScadCall> program() {
        std::vector<ScadCall> calls;
        while (mTok.kind != ScadToken::Kind::End) {
            ScadCall call;
            if (statement(call, 0)) {
                if (!call.name.empty()) calls.push_back(std::move(call));
            } else {
                recover();
            }
        }
        return calls;
    }

private:
    SourcePos at(uint32_t offset) const { return SourcePos{offset, mFile}; }

    void error(uint32_t offset, const std::string& message, const std::string& hint = {}) {
        mSink.error(at(offset), message, hint);
    }

    /// Skips the rest of the top-level statement that failed: to just after the ';' or '}'
    /// that leaves every block opened since it began, so the errors of one broken statement
    /// are one error (a file nested past the limit gave one more per closing brace).
    void recover() {
        while (mTok.kind != ScadToken::Kind::End) {
            const bool end = isPunct(";") || isPunct("}");
            if (isPunct("{")) ++mOpenBlocks;
            if (isPunct("}") && mOpenBlocks > 0) --mOpenBlocks;
            advance();
            if (end && mOpenBlocks == 0) return;
        }
    }

    /// advance() past `{` or `}`, counting the blocks left open (recover() closes them).
    void advanceBrace() {
        mOpenBlocks += isPunct("{") ? 1 : -1;
        advance();
    }

    bool isPunct(const char* p) const {
        return mTok.kind == ScadToken::Kind::Punct && mTok.text == p;
    }

    bool expect(const char* p, const char* where) {
        if (isPunct(p)) {
            advance();
            return true;
        }
        error(mTok.offset,
              std::string("expected '") + p + "' " + where + ", found " + describe(mTok));
        return false;
    }

    static std::string describe(const ScadToken& t) {
        switch (t.kind) {
            case ScadToken::Kind::End: return "the end of the file";
            case ScadToken::Kind::Name: return "'" + t.text + "'";
            case ScadToken::Kind::Number: return "a number";
            case ScadToken::Kind::String: return "a string";
            case ScadToken::Kind::Punct: return "'" + t.text + "'";
            case ScadToken::Kind::Bad: return "'" + t.text + "'";
        }
        return "?";
    }

    /// One statement: `;` alone (call left empty), or [modifier] name(args) followed by `;`,
    /// one child statement or a `{ … }` block. False after a reported error.
    bool statement(ScadCall& call, int depth) {
        if (isPunct(";")) {
            advance();
            return true;
        }
        if (depth > kMaxCsgDepth) {
            error(mTok.offset, "modules nested too deeply (more than " +
                                   std::to_string(kMaxCsgDepth) + " levels)");
            return false;
        }
        if (mTok.kind == ScadToken::Kind::Punct && mTok.text.size() == 1 &&
            std::string("%*#!").find(mTok.text[0]) != std::string::npos) {
            call.modifier = mTok.text[0];
            advance();
        }
        if (mTok.kind != ScadToken::Kind::Name) {
            error(mTok.offset, "expected a module name, found " + describe(mTok),
                  "a .csg file is a tree of calls such as cube(size = [1, 1, 1]);");
            return false;
        }
        call.name = mTok.text;
        call.pos = at(mTok.offset);
        advance();
        if (!expect("(", "after the module name")) return false;
        if (!arguments(call)) return false;
        if (isPunct(";")) {
            advance();
            return true;
        }
        if (isPunct("{")) {
            advanceBrace();
            while (!isPunct("}")) {
                if (mTok.kind == ScadToken::Kind::End) {
                    error(call.pos.offset, "the block of '" + call.name + "' is not closed",
                          "add the missing '}'");
                    return false;
                }
                ScadCall child;
                if (!statement(child, depth + 1)) return false;
                if (!child.name.empty()) call.children.push_back(std::move(child));
            }
            advanceBrace();
            return true;
        }
        ScadCall child;  // a single child without braces
        if (!statement(child, depth + 1)) return false;
        if (!child.name.empty()) call.children.push_back(std::move(child));
        return true;
    }

    bool arguments(ScadCall& call) {
        while (!isPunct(")")) {
            ScadArg a;
            a.pos = at(mTok.offset);
            if (mTok.kind == ScadToken::Kind::Name && peekIsAssign()) {
                a.name = mTok.text;
                advance();
                advance();  // '='
            }
            if (!value(a.value, 0)) return false;
            call.args.push_back(std::move(a));
            if (isPunct(",")) {
                advance();
                continue;
            }
            if (!isPunct(")")) {
                error(mTok.offset, "expected ',' or ')' in the arguments of '" + call.name +
                                       "', found " + describe(mTok));
                return false;
            }
        }
        advance();
        return true;
    }

    bool value(ScadValue& v, int depth) {
        v.pos = at(mTok.offset);
        if (depth > kMaxNesting) {
            error(mTok.offset, "vectors nested too deeply (more than " +
                                   std::to_string(kMaxNesting) + " levels)");
            return false;
        }
        if (isPunct("-") || isPunct("+")) {
            const bool negative = mTok.text == "-";
            advance();
            if (mTok.kind != ScadToken::Kind::Number) {
                error(mTok.offset, "expected a number after the sign, found " + describe(mTok),
                      "a .csg file holds literal values only");
                return false;
            }
            v.kind = ScadValue::Kind::Number;
            v.number = negative ? -mTok.number : mTok.number;
            advance();
            return true;
        }
        switch (mTok.kind) {
            case ScadToken::Kind::Number:
                v.kind = ScadValue::Kind::Number;
                v.number = mTok.number;
                advance();
                return true;
            case ScadToken::Kind::String:
                v.kind = ScadValue::Kind::String;
                v.text = mTok.text;
                advance();
                return true;
            case ScadToken::Kind::Name:
                if (mTok.text == "true" || mTok.text == "false") {
                    v.kind = ScadValue::Kind::Bool;
                    v.boolean = mTok.text == "true";
                } else if (mTok.text == "undef") {
                    v.kind = ScadValue::Kind::Undef;
                } else if (mTok.text == "inf" || mTok.text == "nan") {
                    v.kind = ScadValue::Kind::Number;
                    v.number = mTok.text == "inf" ? INFINITY : NAN;
                } else {
                    error(mTok.offset, "'" + mTok.text + "' is not a literal value",
                          "a .csg file holds numbers, booleans, strings, vectors and undef only");
                    return false;
                }
                advance();
                return true;
            default: break;
        }
        if (isPunct("[")) {
            v.kind = ScadValue::Kind::Vector;
            advance();
            while (!isPunct("]")) {
                ScadValue item;
                if (!value(item, depth + 1)) return false;
                v.items.push_back(std::move(item));
                if (isPunct(",")) {
                    advance();
                } else if (!isPunct("]")) {
                    error(mTok.offset, "expected ',' or ']' in a vector, found " + describe(mTok));
                    return false;
                }
            }
            advance();
            return true;
        }
        error(mTok.offset, "expected a value, found " + describe(mTok));
        return false;
    }

    /// Whether the token after the current name is '=' (a named argument).
    bool peekIsAssign() const {
        size_t i = mPos;
        while (i < mText.size()) {
            if (std::isspace(static_cast<unsigned char>(mText[i]))) {
                ++i;
            } else if (mText.compare(i, 2, "//") == 0) {
                while (i < mText.size() && mText[i] != '\n') ++i;
            } else if (mText.compare(i, 2, "/*") == 0) {
                const size_t end = mText.find("*/", i + 2);
                i = end == std::string::npos ? mText.size() : end + 2;
            } else {
                return mText[i] == '=' && (i + 1 >= mText.size() || mText[i + 1] != '=');
            }
        }
        return false;
    }

    void skipSpace() {
        while (mPos < mText.size()) {
            if (std::isspace(static_cast<unsigned char>(mText[mPos]))) {
                ++mPos;
            } else if (mText.compare(mPos, 2, "//") == 0) {
                while (mPos < mText.size() && mText[mPos] != '\n') ++mPos;
            } else if (mText.compare(mPos, 2, "/*") == 0) {
                const size_t end = mText.find("*/", mPos + 2);
                if (end == std::string::npos) {
                    error(static_cast<uint32_t>(mPos), "comment is not closed",
                          "add the missing */");
                    mPos = mText.size();
                } else {
                    mPos = end + 2;
                }
            } else {
                return;
            }
        }
    }

    void advance() {
        skipSpace();
        mTok = ScadToken{};
        mTok.offset = static_cast<uint32_t>(mPos);
        if (mPos >= mText.size()) return;
        const char c = mText[mPos];
        auto isNameChar = [](char ch) {
            return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_';
        };
        if (std::isalpha(static_cast<unsigned char>(c)) || c == '_' || c == '$') {
            const size_t start = mPos++;
            while (mPos < mText.size() && isNameChar(mText[mPos])) ++mPos;
            mTok.kind = ScadToken::Kind::Name;
            mTok.text = mText.substr(start, mPos - start);
        } else if (std::isdigit(static_cast<unsigned char>(c)) ||
                   (c == '.' && mPos + 1 < mText.size() &&
                    std::isdigit(static_cast<unsigned char>(mText[mPos + 1])))) {
            number();
        } else if (c == '"') {
            string();
        } else if (std::string("()[]{},;=%*#!-+").find(c) != std::string::npos) {
            mTok.kind = ScadToken::Kind::Punct;
            mTok.text = std::string(1, c);
            ++mPos;
        } else {
            mTok.kind = ScadToken::Kind::Bad;
            mTok.text = std::string(1, c);
            error(mTok.offset, std::string("unexpected character '") + c + "'");
            ++mPos;
        }
    }

    void number() {
        const size_t start = mPos;
        auto digits = [&] {
            while (mPos < mText.size() && std::isdigit(static_cast<unsigned char>(mText[mPos])))
                ++mPos;
        };
        digits();
        if (mPos < mText.size() && mText[mPos] == '.') {
            ++mPos;
            digits();
        }
        if (mPos < mText.size() && (mText[mPos] == 'e' || mText[mPos] == 'E')) {
            size_t e = mPos + 1;
            if (e < mText.size() && (mText[e] == '+' || mText[e] == '-')) ++e;
            if (e < mText.size() && std::isdigit(static_cast<unsigned char>(mText[e]))) {
                mPos = e;
                digits();
            }
        }
        const std::string spelled = mText.substr(start, mPos - start);
        mTok.kind = ScadToken::Kind::Number;
        mTok.number = std::strtod(spelled.c_str(), nullptr);
        if (!std::isfinite(mTok.number)) {
            error(mTok.offset, "number " + spelled + " is too large for a double");
            mTok.kind = ScadToken::Kind::Bad;
        }
    }

    void string() {
        ++mPos;
        std::string out;
        while (mPos < mText.size() && mText[mPos] != '"') {
            char ch = mText[mPos++];
            if (ch == '\\' && mPos < mText.size()) {
                const char e = mText[mPos++];
                ch = e == 'n' ? '\n' : e == 't' ? '\t' : e == 'r' ? '\r' : e;
            }
            out += ch;
        }
        if (mPos >= mText.size()) {
            error(mTok.offset, "string is not closed", "add the missing '\"'");
            mTok.kind = ScadToken::Kind::Bad;
            return;
        }
        ++mPos;
        mTok.kind = ScadToken::Kind::String;
        mTok.text = std::move(out);
    }

    const std::string& mText;
    uint32_t mFile;
    DiagnosticSink& mSink;
    size_t mPos = 0;
    ScadToken mTok;
    int64_t mOpenBlocks = 0;  ///< blocks of the current top-level statement not yet closed
};

}  // namespace

std::vector<ScadCall> parseOpenScadCsg(const std::string& text, uint32_t file,
                                       DiagnosticSink& sink) {
    return Parser(text, file, sink).program();
}

}  // namespace kerf
