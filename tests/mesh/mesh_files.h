/// @file tests/mesh/mesh_files.h
/// @brief Crafted mesh files for the loader tests: one octahedron written in every format the
/// loader reads, and helpers to compare meshes as sets of oriented triangles. Header-only
/// because the test build compiles only *_test.cpp files.
#pragma once

#include "mesh/triangle_mesh.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

namespace kerf::test {

/// An octahedron around (0.5, -2, 3) with radius 1.25: every coordinate is exact in float,
/// so every format stores it without rounding and the loaded triangles compare exactly.
inline const Vec3 kOctaCenter(0.5, -2.0, 3.0);
inline constexpr double kOctaRadius = 1.25;

/// Vertices at the origin (the glTF file places them by its node's translation).
inline std::vector<Vec3> octahedronVerticesAtOrigin() {
    const double r = kOctaRadius;
    return {{r, 0, 0}, {-r, 0, 0}, {0, r, 0}, {0, -r, 0}, {0, 0, r}, {0, 0, -r}};
}

inline std::vector<Vec3> octahedronVertices() {
    std::vector<Vec3> v = octahedronVerticesAtOrigin();
    for (Vec3& p : v) p += kOctaCenter;
    return v;
}

/// Eight faces, counter-clockwise seen from outside: (±x, ±y, ±z), swapped when the signs'
/// product is negative.
inline std::vector<std::array<uint32_t, 3>> octahedronTriangles() {
    std::vector<std::array<uint32_t, 3>> t;
    for (uint32_t sx = 0; sx < 2; ++sx)
        for (uint32_t sy = 0; sy < 2; ++sy)
            for (uint32_t sz = 0; sz < 2; ++sz) {
                const uint32_t x = sx, y = 2 + sy, z = 4 + sz;
                if ((sx + sy + sz) % 2 == 0)
                    t.push_back({x, y, z});
                else
                    t.push_back({x, z, y});
            }
    return t;
}

inline TriangleMesh octahedronMesh() {
    TriangleMesh m;
    m.positions = octahedronVertices();
    m.triangles = octahedronTriangles();
    return m;
}

using OrientedTriangle = std::array<std::array<double, 3>, 3>;

/// The mesh as a sorted list of triangles, each rotated to start at its smallest corner
/// (keeps orientation): two meshes are the same surface iff these are equal.
inline std::vector<OrientedTriangle> canonicalTriangles(const TriangleMesh& m) {
    std::vector<OrientedTriangle> out;
    for (const auto& t : m.triangles) {
        OrientedTriangle tri;
        for (int c = 0; c < 3; ++c) {
            const Vec3& p = m.positions[t[c]];
            tri[c] = {p.x, p.y, p.z};
        }
        const auto smallest = std::min_element(tri.begin(), tri.end()) - tri.begin();
        std::rotate(tri.begin(), tri.begin() + smallest, tri.end());
        out.push_back(tri);
    }
    std::sort(out.begin(), out.end());
    return out;
}

inline std::string objText() {
    std::ostringstream s;
    s << "# octahedron\n";
    for (const Vec3& p : octahedronVertices()) s << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
    for (const auto& t : octahedronTriangles())
        s << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
    return s.str();
}

inline std::string plyHeader(const char* format, size_t vertices, size_t faces) {
    std::ostringstream s;
    s << "ply\nformat " << format << " 1.0\nelement vertex " << vertices
      << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << faces
      << "\nproperty list uchar int vertex_indices\nend_header\n";
    return s.str();
}

inline std::string plyAsciiText() {
    std::ostringstream s;
    s << plyHeader("ascii", 6, 8);
    for (const Vec3& p : octahedronVertices()) s << p.x << ' ' << p.y << ' ' << p.z << '\n';
    for (const auto& t : octahedronTriangles())
        s << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    return s.str();
}

template <class T>
void appendBytes(std::string& out, T value) {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));  // the tests run on little-endian x86-64
    out.append(bytes, sizeof(T));
}

inline std::string plyBinaryText() {
    std::string s = plyHeader("binary_little_endian", 6, 8);
    for (const Vec3& p : octahedronVertices())
        for (int i = 0; i < 3; ++i) appendBytes(s, static_cast<float>(p[i]));
    for (const auto& t : octahedronTriangles()) {
        appendBytes(s, static_cast<uint8_t>(3));
        for (uint32_t v : t) appendBytes(s, static_cast<int32_t>(v));
    }
    return s;
}

inline Vec3 faceNormal(const std::vector<Vec3>& v, const std::array<uint32_t, 3>& t) {
    return glm::normalize(glm::cross(v[t[1]] - v[t[0]], v[t[2]] - v[t[0]]));
}

inline std::string stlAsciiText() {
    const auto v = octahedronVertices();
    std::ostringstream s;
    s << "solid octahedron\n";
    for (const auto& t : octahedronTriangles()) {
        const Vec3 n = faceNormal(v, t);
        s << "  facet normal " << n.x << ' ' << n.y << ' ' << n.z << "\n    outer loop\n";
        for (uint32_t i : t)
            s << "      vertex " << v[i].x << ' ' << v[i].y << ' ' << v[i].z << '\n';
        s << "    endloop\n  endfacet\n";
    }
    s << "endsolid octahedron\n";
    return s.str();
}

/// A binary STL of `facets` (each 12 floats: normal, three corners); the header must not
/// start with "solid", or readers take it for ASCII.
inline std::string stlBinary(const std::vector<std::array<float, 12>>& facets, uint32_t count) {
    std::string s(80, ' ');
    s.replace(0, 14, "kerf test mesh");
    appendBytes(s, count);
    for (const auto& f : facets) {
        for (float x : f) appendBytes(s, x);
        appendBytes(s, static_cast<uint16_t>(0));
    }
    return s;
}

inline std::vector<std::array<float, 12>> octahedronFacets() {
    const auto v = octahedronVertices();
    std::vector<std::array<float, 12>> facets;
    for (const auto& t : octahedronTriangles()) {
        const Vec3 n = faceNormal(v, t);
        std::array<float, 12> f{};
        for (int i = 0; i < 3; ++i) f[i] = static_cast<float>(n[i]);
        for (int c = 0; c < 3; ++c)
            for (int i = 0; i < 3; ++i) f[3 + 3 * c + i] = static_cast<float>(v[t[c]][i]);
        facets.push_back(f);
    }
    return facets;
}

inline std::string stlBinaryText() { return stlBinary(octahedronFacets(), 8); }

inline std::string base64(const std::string& bytes) {
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < bytes.size(); i += 3) {
        uint32_t chunk = uint32_t(uint8_t(bytes[i])) << 16;
        if (i + 1 < bytes.size()) chunk |= uint32_t(uint8_t(bytes[i + 1])) << 8;
        if (i + 2 < bytes.size()) chunk |= uint32_t(uint8_t(bytes[i + 2]));
        out += table[(chunk >> 18) & 63];
        out += table[(chunk >> 12) & 63];
        out += i + 1 < bytes.size() ? table[(chunk >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? table[chunk & 63] : '=';
    }
    return out;
}

/// The octahedron's glTF buffer: positions at the origin (float32), then indices (uint16).
inline std::string gltfBuffer() {
    std::string buffer;
    for (const Vec3& p : octahedronVerticesAtOrigin())
        for (int i = 0; i < 3; ++i) appendBytes(buffer, static_cast<float>(p[i]));
    for (const auto& t : octahedronTriangles())
        for (uint32_t v : t) appendBytes(buffer, static_cast<uint16_t>(v));
    return buffer;
}

/// glTF 2.0 JSON for the octahedron: one node whose translation moves it to kOctaCenter
/// (with `mirrored`, also a scale of -1 in x, which leaves the symmetric octahedron's
/// positions in place but reverses its triangles' winding). `uri` empty: the buffer is a
/// .glb's binary chunk.
inline std::string gltfJson(const std::string& uri, bool mirrored) {
    const size_t positionBytes = 6 * 3 * sizeof(float);
    const size_t indexBytes = 8 * 3 * sizeof(uint16_t);
    const double r = kOctaRadius;
    std::ostringstream s;
    s << R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],)"
      << R"("nodes": [{"mesh": 0, )" << (mirrored ? R"("scale": [-1, 1, 1], )" : "")
      << R"("translation": [)" << kOctaCenter.x << ", " << kOctaCenter.y << ", " << kOctaCenter.z
      << "]}],"
      << R"("meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "mode": 4}]}],)"
      << R"("accessors": [{"bufferView": 0, "componentType": 5126, "count": 6, "type": "VEC3", )"
      << R"("min": [)" << -r << ", " << -r << ", " << -r << R"(], "max": [)" << r << ", " << r
      << ", " << r << "]},"
      << R"({"bufferView": 1, "componentType": 5123, "count": 24, "type": "SCALAR"}],)"
      << R"("bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": )" << positionBytes
      << R"(, "target": 34962}, {"buffer": 0, "byteOffset": )" << positionBytes
      << R"(, "byteLength": )" << indexBytes << R"(, "target": 34963}],)"
      << R"("buffers": [{"byteLength": )" << positionBytes + indexBytes;
    if (!uri.empty()) s << R"(, "uri": ")" << uri << '"';
    s << "}]}";
    return s.str();
}

/// .gltf with the buffer embedded as a base64 data URI.
inline std::string gltfText(bool mirrored = false) {
    return gltfJson("data:application/octet-stream;base64," + base64(gltfBuffer()), mirrored);
}

/// .glb: a 12-byte header, a JSON chunk padded with spaces and a binary chunk padded with
/// zeros, each to 4 bytes.
inline std::string glbText() {
    std::string json = gltfJson("", false), bin = gltfBuffer();
    json.append((4 - json.size() % 4) % 4, ' ');
    bin.append((4 - bin.size() % 4) % 4, '\0');
    std::string out = "glTF";
    appendBytes(out, uint32_t(2));
    appendBytes(out, uint32_t(12 + 8 + json.size() + 8 + bin.size()));
    appendBytes(out, uint32_t(json.size()));
    out += "JSON" + json;
    appendBytes(out, uint32_t(bin.size()));
    out += std::string("BIN\0", 4) + bin;
    return out;
}

}  // namespace kerf::test
