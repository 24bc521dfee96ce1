/// @file mesh/off_counts.cpp
/// @brief OFF counts against the file's size (mesh/off_counts.h).
#include "mesh/off_counts.h"

#include <cctype>
#include <cstdint>

namespace kerf {
namespace {

constexpr uint64_t kOffMinBytesPerFace = 4;  ///< "1 0\n": Assimp reads faces of any corner count

/// The next whitespace-separated word from `at`, which moves past it.
std::string nextWord(const std::string& data, size_t& at) {
    while (at < data.size() && std::isspace(static_cast<unsigned char>(data[at]))) ++at;
    const size_t start = at;
    while (at < data.size() && !std::isspace(static_cast<unsigned char>(data[at]))) ++at;
    return data.substr(start, at - start);
}

/// The value of a word's leading digits (as Assimp's strtoul10 reads it), or nullopt past 32 bits.
std::optional<uint64_t> leadingCount(const std::string& word) {
    uint64_t v = 0;
    for (const char c : word) {
        if (c < '0' || c > '9') break;
        v = v * 10 + uint64_t(c - '0');
        if (v > 0xffffffffull) return std::nullopt;
    }
    return v;
}

/// Numbers on a vertex row for the header word (3 coordinates, then normals, colours, texture
/// coordinates and a homogeneous one as its prefix letters say), `dimension` for nOFF.
uint64_t numbersPerVertex(const std::string& header, uint64_t dimension) {
    const std::string prefix = header.substr(0, header.size() - 3);
    uint64_t n = prefix.find('n') != std::string::npos ? dimension : 3;
    if (prefix.find("ST") != std::string::npos) n += 2;
    if (prefix.find('C') != std::string::npos) n += 3;
    if (prefix.find('N') != std::string::npos) n += 3;
    if (prefix.find('4') != std::string::npos) n += 1;
    return n;
}

}  // namespace

bool looksLikeOff(const std::string& data) {
    size_t at = 0;
    const std::string word = nextWord(data, at);
    if (word.size() < 3 || word.compare(word.size() - 3, 3, "OFF") != 0) return false;
    for (const char c : word)
        if (!std::isalnum(static_cast<unsigned char>(c))) return false;
    return true;
}

std::optional<std::string> offCountsShortfall(const std::string& data) {
    size_t at = 0;
    std::string word = nextWord(data, at);
    uint64_t perVertex = 3;
    if (looksLikeOff(data)) {
        uint64_t dimension = 3;
        if (word.find('n') != std::string::npos && word.find('n') < word.size() - 3)
            dimension = leadingCount(nextWord(data, at)).value_or(0xffffffffull);
        perVertex = numbersPerVertex(word, dimension);
        word = nextWord(data, at);
    }
    const std::optional<uint64_t> vertices = leadingCount(word);
    const std::string faceWord = nextWord(data, at);
    const std::optional<uint64_t> faces = leadingCount(faceWord);
    if (!vertices || !faces)
        return "OFF header: the " + std::string(!vertices ? "vertex" : "face") + " count '" +
               (!vertices ? word : faceWord).substr(0, 24) + "' does not fit 32 bits";
    const uint64_t needed = *vertices * 2 * perVertex + *faces * kOffMinBytesPerFace;
    const uint64_t left = data.size() - at;
    if (needed > left)
        return "truncated OFF file: the header declares " + std::to_string(*vertices) +
               " vertices and " + std::to_string(*faces) + " faces (at least " +
               std::to_string(needed) + " bytes) but " + std::to_string(left) + " bytes follow it";
    return std::nullopt;
}

}  // namespace kerf
