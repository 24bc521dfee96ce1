/// @file tests/util/vdb_file_bytes.h
/// @brief The .vdb layout tests' tools: a file's bytes read and written whole, and what each
/// reader (level set, fog) says of a file.
#pragma once

#include "volume/grids/vdb_fog.h"
#include "volume/grids/vdb_level_set.h"

#include <fstream>
#include <iterator>
#include <string>

namespace kerf::test {

inline std::string fileBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline void writeBytes(const std::string& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

/// "" when the reader (loadVdbFog with `fog`, else loadLevelSet) takes the file, its message
/// otherwise, "UNEXPECTED: …" for any other exception.
inline std::string readerVerdict(const std::string& path, bool fog) {
    try {
        if (fog)
            loadVdbFog(path, "");
        else
            loadLevelSet(path);
    } catch (const VdbError& e) {
        return e.what();
    } catch (const VdbFogError& e) {
        return e.what();
    } catch (const std::exception& e) {
        return std::string("UNEXPECTED: ") + e.what();
    }
    return "";
}

}  // namespace kerf::test
