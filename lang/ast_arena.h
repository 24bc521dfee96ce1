/// @file lang/ast_arena.h
/// @brief Storage for the syntax tree of one file: expressions in large blocks (no allocation
/// and no allocator header per node) and names interned once, so a name is one pointer.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <memory>
#include <new>
#include <string>
#include <type_traits>
#include <unordered_set>
#include <vector>

namespace kerf {

/// An interned name: 8 bytes where a std::string takes 32. Reads as a const std::string&.
class Name {
public:
    Name() = default;
    explicit Name(const std::string* text) : mText(text) {}

    const std::string& str() const { return mText ? *mText : emptyString(); }
    operator const std::string&() const { return str(); }
    bool empty() const { return str().empty(); }

    friend bool operator==(const Name& a, const char* b) { return a.str() == b; }
    friend bool operator==(const Name& a, const std::string& b) { return a.str() == b; }
    friend bool operator!=(const Name& a, const char* b) { return a.str() != b; }
    friend bool operator!=(const Name& a, const std::string& b) { return a.str() != b; }
    friend bool operator==(const std::string& a, const Name& b) { return a == b.str(); }
    friend bool operator==(const char* a, const Name& b) { return a == b.str(); }
    friend std::string operator+(const std::string& a, const Name& b) { return a + b.str(); }
    friend std::string operator+(const char* a, const Name& b) { return a + b.str(); }
    friend std::string operator+(const Name& a, const std::string& b) { return a.str() + b; }
    friend std::string operator+(const Name& a, const char* b) { return a.str() + b; }

private:
    static const std::string& emptyString() {
        static const std::string empty;
        return empty;
    }
    const std::string* mText = nullptr;
};

/// A bump allocator for trivially destructible nodes plus a table of interned names. The
/// parser uses the blocks as scratch space for one statement at a time (reset); the names
/// live as long as the Program.
class AstArena {
public:
    AstArena() = default;
    AstArena(const AstArena&) = delete;
    AstArena& operator=(const AstArena&) = delete;

    /// Copies `n` values into the arena, side by side; null for n = 0.
    template <class T>
    T* copy(const T* values, size_t n) {
        static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>);
        if (n == 0) return nullptr;
        void* p = allocate(n * sizeof(T), alignof(T));
        std::memcpy(p, values, n * sizeof(T));
        return static_cast<T*>(p);
    }

    /// The one copy of `text` in this arena.
    Name intern(const std::string& text) { return Name(&*mNames.insert(text).first); }

    /// Bytes handed out since the last reset (without padding: every node type is a multiple
    /// of 8 bytes, aligned to 8).
    size_t handedOut() const { return mHandedOut; }
    /// Forgets every node (the interned names stay); the first block is kept for reuse.
    void reset() {
        if (mBlocks.size() > 1) mBlocks.resize(1);
        if (!mBlocks.empty()) {
            mBlock = reinterpret_cast<std::byte*>(mBlocks.front().get());
            mBlockSize = mFirstBlockSize;
        }
        mUsed = 0;
        mHandedOut = 0;
    }

private:
    void* allocate(size_t bytes, size_t align) {
        size_t at = (mUsed + align - 1) & ~(align - 1);
        if (!mBlock || at + bytes > mBlockSize) {
            // A request larger than a block gets a block of its own.
            mBlockSize = std::max(kBlockBytes, bytes);
            mBlocks.emplace_back(new std::max_align_t[(mBlockSize + sizeof(std::max_align_t) - 1) /
                                                      sizeof(std::max_align_t)]);
            mBlock = reinterpret_cast<std::byte*>(mBlocks.back().get());
            if (mBlocks.size() == 1) mFirstBlockSize = mBlockSize;
            at = 0;
        }
        mUsed = at + bytes;
        mHandedOut += bytes;
        return mBlock + at;
    }

    static constexpr size_t kBlockBytes = 64 * 1024;
    std::vector<std::unique_ptr<std::max_align_t[]>> mBlocks;
    std::byte* mBlock = nullptr;
    size_t mBlockSize = 0;
    size_t mUsed = 0;
    size_t mFirstBlockSize = 0;
    size_t mHandedOut = 0;
    std::unordered_set<std::string> mNames;
};

}  // namespace kerf
