/// @file lang/token_window.h
/// @brief The tokens the parser may still look at, lexed on demand (parse memory follows the
/// statement being parsed, not the file).
#pragma once

#include "lang/lexer.h"

#include <deque>
#include <functional>

namespace kerf {

/// The tokens the parser may still look at, lexed on demand. A deque, so that references to
/// tokens stay valid while more are lexed; the tokens before a statement are dropped.
class TokenWindow {
public:
    explicit TokenWindow(std::function<Token()> source) : mSource(std::move(source)) {}

    /// Token i of the file (absolute index, not dropped yet); End past the end.
    const Token& at(size_t i) {
        while (mBase + mTokens.size() <= i &&
               (mTokens.empty() || mTokens.back().kind != TokenKind::End))
            mTokens.push_back(mSource());
        return i - mBase < mTokens.size() ? mTokens[i - mBase] : mTokens.back();
    }
    /// Forgets the tokens before index i.
    void dropBefore(size_t i) {
        while (mBase < i && mTokens.size() > 1) {
            mTokens.pop_front();
            ++mBase;
        }
    }

private:
    std::function<Token()> mSource;
    std::deque<Token> mTokens;
    size_t mBase = 0;  // index of mTokens.front()
};

}  // namespace kerf
