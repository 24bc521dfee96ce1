/// @file volume/grids/vdb_layout_reader.h
/// @brief The byte reader behind the .vdb layout checks (checked_vdb_layout.cpp,
/// checked_vdb_tree.cpp): every read checked against the bytes left, in 64-bit arithmetic,
/// each failure a VdbLayoutProblem saying what and at which byte.
#pragma once

#include <cstdint>
#include <fstream>
#include <stdexcept>
#include <string>

namespace kerf::vdb_layout {

/// Thrown inside the check with what is wrong; checkVdbLayout returns its text.
struct VdbLayoutProblem : std::runtime_error {
    using std::runtime_error::runtime_error;
};

class VdbLayoutReader {
public:
    explicit VdbLayoutReader(const std::string& path) : mIn(path, std::ios::binary) {
        if (!mIn) throw VdbLayoutProblem("cannot open it for reading");
        mIn.seekg(0, std::ios::end);
        const std::streamoff end = mIn.tellg();
        if (end < 0) throw VdbLayoutProblem("cannot find its size");
        mSize = uint64_t(end);
        mIn.seekg(0);
    }

    uint64_t size() const { return mSize; }
    uint64_t at() const { return mPos; }
    uint64_t left() const { return mSize - mPos; }

    void seek(uint64_t pos) {
        mPos = pos;
        mIn.seekg(std::streamoff(pos));
    }

    /// n bytes of `what`, or the truncation named.
    void read(void* out, uint64_t n, const std::string& what) {
        need(n, what);
        mIn.read(static_cast<char*>(out), std::streamsize(n));
        if (!mIn)
            throw VdbLayoutProblem("cannot read " + what + " at byte " + std::to_string(mPos));
        mPos += n;
    }
    void need(uint64_t n, const std::string& what) const {
        if (n > left())
            throw VdbLayoutProblem("truncated at byte " + std::to_string(mPos) + ": " + what +
                                   " needs " + std::to_string(n) + " bytes, " +
                                   std::to_string(left()) + " remain of " + std::to_string(mSize));
    }
    template <typename T>
    T value(const std::string& what) {
        T v;
        read(&v, sizeof v, what);
        return v;
    }
    /// A length-prefixed string, its length checked against the bytes left (and `most`).
    std::string string(const std::string& what, uint64_t most = UINT64_MAX) {
        const uint64_t start = mPos;
        const uint64_t n = value<uint32_t>("the length of " + what);
        if (n > left() || n > most)
            throw VdbLayoutProblem("bad length at byte " + std::to_string(start) + ": " + what +
                                   " claims " + std::to_string(n) + " bytes, " +
                                   (n > left() ? std::to_string(left()) + " remain"
                                               : "at most " + std::to_string(most) + " allowed"));
        std::string s(n, '\0');
        if (n) read(s.data(), n, what);
        return s;
    }
    void skip(uint64_t n, const std::string& what) {
        need(n, what);
        seek(mPos + n);
    }

private:
    std::ifstream mIn;
    uint64_t mSize = 0;
    uint64_t mPos = 0;
};

}  // namespace kerf::vdb_layout
