// OBJ, binary PLY and binary STL encoders, and the atomic write of their bytes.
#include "io/mesh_writers.h"

#include "io/mesh_weld.h"
#include "io/number_text.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>

namespace kerf {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__,
              "PLY and STL are written by copying little-endian words");

namespace {

template <class T>
void put(std::string& out, T value) {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    out.append(bytes, sizeof(T));
}

std::string encodeObj(const MeshArrays& m) {
    std::string out = "# kerf mesh: " + std::to_string(m.vertexCount) + " vertices, " +
                      std::to_string(m.triangleCount) + " triangles\n";
    out.reserve(m.vertexCount * 40 + m.triangleCount * 24);
    for (size_t i = 0; i < m.vertexCount; ++i) {
        out += "v";
        for (int a = 0; a < 3; ++a) {
            out += ' ';
            appendExactNumber(out, m.xyz[3 * i + size_t(a)]);
        }
        out += '\n';
    }
    for (size_t t = 0; t < m.triangleCount; ++t) {
        out += "f";
        for (int k = 0; k < 3; ++k) {
            out += ' ';
            out += std::to_string(uint64_t(m.indices[3 * t + size_t(k)]) + 1);
        }
        out += '\n';
    }
    return out;
}

/// The vertex to write first in a binary PLY: one whose first byte is not '\n'. Assimp 5.2
/// takes a '\n' right after "end_header\n" for part of the line end and reads every value
/// after it one byte off (kerf's reader works around it, mesh/ply_line_end.h; other Assimp
/// readers do not).
uint32_t firstVertexNotNewline(const MeshArrays& m) {
    for (uint32_t i = 0; i < m.vertexCount; ++i) {
        const float x = float(m.xyz[3 * size_t(i)]);
        unsigned char low;
        std::memcpy(&low, &x, 1);
        if (low != '\n') return i;
    }
    return 0;
}

std::string encodePly(const MeshArrays& m) {
    std::string out = "ply\nformat binary_little_endian 1.0\ncomment kerf mesh\nelement vertex " +
                      std::to_string(m.vertexCount) +
                      "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
                      std::to_string(m.triangleCount) +
                      "\nproperty list uchar uint vertex_indices\nend_header\n";
    out.reserve(out.size() + 12 * m.vertexCount + 13 * m.triangleCount);
    const uint32_t first = firstVertexNotNewline(m);
    const auto order = [first](uint32_t i) { return i == 0 ? first : i == first ? 0 : i; };
    for (uint32_t i = 0; i < m.vertexCount; ++i)
        for (int a = 0; a < 3; ++a) put(out, float(m.xyz[3 * size_t(order(i)) + size_t(a)]));
    for (size_t t = 0; t < m.triangleCount; ++t) {
        put(out, uint8_t(3));
        for (int k = 0; k < 3; ++k) put(out, order(m.indices[3 * t + size_t(k)]));
    }
    return out;
}

std::string encodeStl(const MeshArrays& m) {
    // The header must not begin with "solid", which readers take for ASCII STL.
    std::string out = "binary STL written by kerf";
    out.resize(80, ' ');
    put(out, uint32_t(m.triangleCount));
    out.reserve(out.size() + 50 * m.triangleCount);
    for (size_t t = 0; t < m.triangleCount; ++t) {
        double p[3][3];
        for (int k = 0; k < 3; ++k)
            for (int a = 0; a < 3; ++a)
                p[k][a] = m.xyz[3 * size_t(m.indices[3 * t + size_t(k)]) + size_t(a)];
        const double u[3] = {p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]};
        const double v[3] = {p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
        double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                       u[0] * v[1] - u[1] * v[0]};
        const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (double& c : n) c = len > 0.0 ? c / len : 0.0;
        for (const double c : n) put(out, float(c));
        for (int k = 0; k < 3; ++k)
            for (int a = 0; a < 3; ++a) put(out, float(p[k][a]));
        put(out, uint16_t(0));
    }
    return out;
}

}  // namespace

bool meshFormatFromPath(const std::string& path, MeshFormat& format) {
    const size_t dot = path.find_last_of('.');
    const size_t slash = path.find_last_of('/');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return false;
    std::string ext = path.substr(dot + 1);
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (ext == "obj")
        format = MeshFormat::Obj;
    else if (ext == "ply")
        format = MeshFormat::Ply;
    else if (ext == "stl")
        format = MeshFormat::Stl;
    else
        return false;
    return true;
}

std::string encodeMesh(MeshFormat format, const MeshArrays& mesh) {
    // One vertex per position as written: OBJ writes the doubles, PLY and STL floats.
    const WeldedMesh welded = weldWrittenPositions(mesh, format != MeshFormat::Obj);
    MeshArrays joined;
    joined.xyz = welded.xyz.data();
    joined.vertexCount = welded.xyz.size() / 3;
    joined.indices = welded.indices.data();
    joined.triangleCount = welded.indices.size() / 3;
    switch (format) {
        case MeshFormat::Obj: return encodeObj(joined);
        case MeshFormat::Ply: return encodePly(joined);
        default: return encodeStl(joined);
    }
}

void writeMeshFile(const std::string& path, MeshFormat format, const MeshArrays& mesh) {
    const std::string bytes = encodeMesh(format, mesh);
    const std::string error = replaceFile(path, "", bytes.data(), bytes.size());
    if (!error.empty()) throw MeshWriteError(cannotWrite(path, error));
}

}  // namespace kerf
