// A binary PLY's header end respelt for Assimp 5.2 (mesh/ply_line_end.h).
#include "mesh/ply_line_end.h"

#include <fstream>
#include <iterator>

namespace kerf {

namespace {

/// Bytes of the file's start searched for the header's end: Assimp reads longer headers, but
/// a header of 64 kB is thousands of lines.
constexpr std::streamsize kHeaderBytes = 65536;

}  // namespace

std::optional<std::string> plyWithCrLfHeaderEnd(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::string head(size_t(kHeaderBytes), '\0');
    in.read(head.data(), kHeaderBytes);
    head.resize(size_t(in.gcount()));
    if (head.compare(0, 4, "ply\n") != 0 && head.compare(0, 5, "ply\r\n") != 0) return std::nullopt;
    const std::string endLine = "\nend_header\n";
    const size_t end = head.find(endLine);
    if (end == std::string::npos || end + endLine.size() >= head.size()) return std::nullopt;
    const size_t data = end + endLine.size();
    const size_t format = head.find("\nformat ");
    if (format == std::string::npos || format > end ||
        head.compare(format + 8, 7, "binary_") != 0 || head[data] != '\n')
        return std::nullopt;
    in.clear();
    in.seekg(0);
    std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (bytes.size() <= data) return std::nullopt;
    bytes.insert(data - 1, 1, '\r');
    return bytes;
}

}  // namespace kerf
