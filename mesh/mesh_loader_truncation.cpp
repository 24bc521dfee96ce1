// Sizes of binary STL and PLY files against their headers. Only what the header declares is
// walked (for PLY lists, each count is read to skip its items), never beyond the file's end.
#include "mesh/mesh_loader_truncation.h"

#include "mesh/off_counts.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

namespace kerf {
namespace {

std::string readAll(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// Whether an STL that starts with "solid" is really ASCII: many CAD exporters write "solid"
/// into a binary file's 80-byte header, and its facets are then mostly unprintable bytes.
bool looksLikeText(const std::string& data) {
    const size_t n = std::min<size_t>(data.size(), 1024);
    for (size_t i = 0; i < n; ++i) {
        const unsigned char c = static_cast<unsigned char>(data[i]);
        if (c < 0x20 && c != '\n' && c != '\r' && c != '\t' && c != '\f' && c != '\v') return false;
        if (c >= 0x7f) return false;
    }
    return true;
}

std::optional<std::string> stlTruncation(const std::string& data) {
    if (data.compare(0, 5, "solid") == 0 && looksLikeText(data)) return std::nullopt;  // ASCII
    if (data.size() < 84)
        return "truncated binary STL: " + std::to_string(data.size()) +
               " bytes, less than the 84 of its header";
    uint32_t facets;
    std::memcpy(&facets, data.data() + 80, 4);  // little-endian by the format, as is x86-64
    const uint64_t needed = 84 + 50 * uint64_t(facets);
    if (data.size() < needed)
        return "truncated binary STL: the header declares " + std::to_string(facets) + " facets (" +
               std::to_string(needed) + " bytes) but the file has " + std::to_string(data.size()) +
               " bytes";
    return std::nullopt;
}

/// A binary glTF (GLB): the 12-byte header's total length and each chunk's length must fit
/// the file (a 640-byte file claiming a 4 GB JSON chunk once took 4.2 GB and 16 s).
std::optional<std::string> glbTruncation(const std::string& data) {
    if (data.size() < 12 || data.compare(0, 4, "glTF") != 0)
        return "not a binary glTF file: " + std::to_string(data.size()) +
               " bytes without the 12-byte 'glTF' header";
    auto word = [&](size_t at) {
        uint32_t v;
        std::memcpy(&v, data.data() + at, 4);  // little-endian by the format
        return uint64_t(v);
    };
    const uint64_t total = word(8);
    if (total > data.size())
        return "truncated binary glTF: the header declares " + std::to_string(total) +
               " bytes but the file has " + std::to_string(data.size());
    for (uint64_t at = 12; at < total;) {
        if (total - at < 8) return "truncated binary glTF: a chunk header is cut off";
        const uint64_t length = word(size_t(at));
        if (length > total - at - 8)
            return "truncated binary glTF: a chunk declares " + std::to_string(length) +
                   " bytes but " + std::to_string(total - at - 8) + " remain";
        at += 8 + length;
    }
    return std::nullopt;
}

/// Bytes of a PLY scalar type, or 0 for a name the format does not have.
uint64_t plyTypeSize(const std::string& type) {
    if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
    if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
    if (type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" ||
        type == "float32")
        return 4;
    if (type == "double" || type == "float64") return 8;
    return 0;
}

struct PlyProperty {
    uint64_t size = 0;       ///< scalar size, or the list's item size
    uint64_t countSize = 0;  ///< 0 for a scalar, else the size of the list's count
    bool countSigned = false;
};

struct PlyElement {
    std::string name;
    uint64_t count = 0;
    std::vector<PlyProperty> properties;
};

/// An ASCII row takes at least two bytes per property (a digit and a separator), so a count
/// the data cannot hold is refused before the importer reserves room for it.
std::optional<std::string> asciiPlyShortfall(const std::vector<PlyElement>& elements,
                                             uint64_t bytes) {
    uint64_t needed = 0;
    for (const PlyElement& e : elements) {
        const uint64_t perRow = 2 * uint64_t(e.properties.size());
        if (perRow != 0 && e.count > (bytes - std::min(bytes, needed)) / perRow)
            return "truncated ASCII PLY: the header declares " + std::to_string(e.count) + " '" +
                   e.name + "' rows, more than its " + std::to_string(bytes) +
                   " bytes of data can hold";
        needed += perRow * e.count;
    }
    return std::nullopt;
}

/// Where a PLY's end_header line starts, or npos. Assimp reads on at the end of the file for
/// ever without one, also when the words are there but not a line of their own
/// ("end_header;1.25 …", kerf_fuzz_mesh).
size_t plyHeaderEnd(const std::string& data) {
    size_t end = data.find("\nend_header\n");
    if (end == std::string::npos) end = data.find("\nend_header\r\n");
    return end == std::string::npos ? end : end + 1;
}

struct PlyHeader {
    bool binary = false, bigEndian = false;
    std::vector<PlyElement> elements;
};

/// The header's lines before end_header: its format and elements, or what is wrong.
std::optional<std::string> parsePlyHeader(const std::string& text, PlyHeader& out) {
    std::istringstream header(text);
    std::string line;
    int lineNumber = 0;
    while (std::getline(header, line)) {
        ++lineNumber;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        std::istringstream words(line);
        std::string key;
        words >> key;
        // Assimp reads on through lines it does not know, and a misspelt keyword or a name
        // with digits in front put its counts out of step (kerf_fuzz_mesh: 80 GB asked for).
        if (lineNumber > 1 && !key.empty() && key != "format" && key != "comment" &&
            key != "obj_info" && key != "element" && key != "property")
            return "PLY header line " + std::to_string(lineNumber) +
                   " does not start with format, comment, obj_info, element or property";
        if (key == "format") {
            std::string format;
            words >> format;
            out.binary = format != "ascii";
            out.bigEndian = format == "binary_big_endian";
        } else if (key == "element") {
            PlyElement e;
            if (!(words >> e.name >> e.count) ||
                !std::isalpha(static_cast<unsigned char>(e.name[0])))
                return "PLY header line " + std::to_string(lineNumber) +
                       " is not 'element NAME COUNT' with a NAME that starts with a letter";
            out.elements.push_back(e);
        } else if (key == "property" && !out.elements.empty()) {
            std::string type;
            words >> type;
            PlyProperty p;
            if (type == "list") {
                std::string countType, itemType;
                words >> countType >> itemType;
                p.countSize = plyTypeSize(countType);
                p.size = plyTypeSize(itemType);
                p.countSigned = countType.find('u') != 0;
                // Unknown types were left to Assimp, which then reserved the declared
                // 4e9 vertices (48 GB) before reading a row (kerf_fuzz_mesh).
                if (p.countSize == 0 || p.size == 0 || p.countSize > 4)
                    return "PLY list property '" + line + "' has a type PLY does not have";
            } else if ((p.size = plyTypeSize(type)) == 0) {
                return "PLY property '" + line + "' has a type PLY does not have";
            }
            out.elements.back().properties.push_back(p);
        }
    }
    return std::nullopt;
}

/// Walks a binary PLY's rows from `pos`, each list's count read to skip its items.
std::optional<std::string> binaryPlyShortfall(const std::string& data, size_t pos,
                                              const PlyHeader& h) {
    const std::vector<PlyElement>& elements = h.elements;
    const bool bigEndian = h.bigEndian;
    const uint64_t size = data.size();
    auto truncated = [&](const PlyElement& e, uint64_t row) {
        return "truncated binary PLY: the data ends after " + std::to_string(row) + " of the " +
               std::to_string(e.count) + " '" + e.name + "' rows its header declares";
    };
    for (const PlyElement& e : elements) {
        for (uint64_t row = 0; row < e.count; ++row) {
            for (const PlyProperty& p : e.properties) {
                if (p.countSize == 0) {
                    if (size - pos < p.size) return truncated(e, row);
                    pos += p.size;
                    continue;
                }
                if (size - pos < p.countSize) return truncated(e, row);
                unsigned char b[4] = {0, 0, 0, 0};
                std::memcpy(b, data.data() + pos, p.countSize);
                int64_t n = 0;
                for (uint64_t i = 0; i < p.countSize; ++i)
                    n |= int64_t(b[bigEndian ? p.countSize - 1 - i : i]) << (8 * i);
                if (p.countSigned && (n >> (8 * p.countSize - 1)) & 1)
                    n -= int64_t(1) << (8 * p.countSize);
                if (n < 0) return "negative list length in " + e.name + " " + std::to_string(row);
                pos += p.countSize;
                if ((size - pos) / p.size < uint64_t(n)) return truncated(e, row);
                pos += uint64_t(n) * p.size;
            }
            // Every row takes at least a byte, so a huge declared count stops here.
            if (pos == size && row + 1 < e.count) return truncated(e, row + 1);
        }
    }
    return std::nullopt;
}

std::optional<std::string> plyTruncation(const std::string& data) {
    // Assimp takes any file starting "ply" as PLY, whatever follows on the line (kerf_fuzz_mesh:
    // "ply\x01…" got past this check and Assimp reserved 48 GB for its vertices).
    if (data.compare(0, 4, "ply\n") != 0 && data.compare(0, 5, "ply\r\n") != 0)
        return "PLY file whose first line is not 'ply'";
    const size_t end = plyHeaderEnd(data);
    if (end == std::string::npos) return "PLY header has no end_header line";
    const size_t pos = data.find('\n', end) + 1;
    PlyHeader h;
    if (auto bad = parsePlyHeader(data.substr(0, end), h)) return bad;
    // Rows of no properties take no bytes, so no size bounds their count; Assimp walked 4e9
    // of them for minutes (kerf_fuzz_mesh, a header whose property lines were misspelt).
    for (const PlyElement& e : h.elements)
        if (e.count > 0 && e.properties.empty())
            return "PLY element '" + e.name + "' declares " + std::to_string(e.count) +
                   " rows but no properties";
    return h.binary ? binaryPlyShortfall(data, pos, h)
                    : asciiPlyShortfall(h.elements, data.size() - pos);
}

}  // namespace

std::optional<std::string> binaryMeshTruncation(const std::string& path) {
    std::string ext = path.size() >= 4 ? path.substr(path.size() - 4) : "";
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    // PLY and binary glTF by their first bytes too: Assimp falls back on them for any name.
    char head[64] = {};
    std::ifstream in(path, std::ios::binary);
    in.read(head, sizeof head);
    const std::string first(head, size_t(in.gcount()));
    const bool ply = ext == ".ply" || first.compare(0, 3, "ply") == 0;
    const bool glb = ext == ".glb" || first.compare(0, 4, "glTF") == 0;
    // OFF by its first word too: Assimp tries its OFF reader on a file of any name.
    const bool off = ext == ".off" || looksLikeOff(first);
    if (ext != ".stl" && !ply && !glb && !off) return std::nullopt;
    const std::string data = readAll(path);
    if (glb) return glbTruncation(data);
    if (ply) return plyTruncation(data);
    return ext == ".stl" ? stlTruncation(data) : offCountsShortfall(data);
}

}  // namespace kerf
