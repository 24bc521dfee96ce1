/// @file tests/util/hostile_image_headers.h
/// @brief Image files that are nothing but a header claiming a huge picture (PNG, JPEG, TIFF,
/// OpenEXR), made byte by byte for the tests that check a texture is refused on its header,
/// before any pixel is allocated. A reader that trusts the header asks for width·height
/// floats per channel: 30,000² RGB is 10.8 GB. Header-only; zlib for PNG's CRCs.
#pragma once

#include <zlib.h>

#include <cstdint>
#include <string>

namespace kerf::test {

namespace hostile_detail {

inline void putBigEndian32(std::string& out, uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) out.push_back(char((v >> shift) & 0xFF));
}
inline void putLittleEndian32(std::string& out, uint32_t v) {
    for (int shift = 0; shift < 32; shift += 8) out.push_back(char((v >> shift) & 0xFF));
}
inline void putLittleEndian16(std::string& out, uint16_t v) {
    out.push_back(char(v & 0xFF));
    out.push_back(char(v >> 8));
}

/// A PNG chunk: length, type, data, CRC over type and data.
inline void pngChunk(std::string& out, const char* type, const std::string& data) {
    putBigEndian32(out, uint32_t(data.size()));
    const std::string body = std::string(type, 4) + data;
    out += body;
    putBigEndian32(
        out, uint32_t(crc32(0, reinterpret_cast<const Bytef*>(body.data()), uInt(body.size()))));
}

/// An OpenEXR attribute: name, type, size, value.
inline void exrAttribute(std::string& out, const std::string& name, const std::string& type,
                         const std::string& value) {
    out += name + '\0' + type + '\0';
    putLittleEndian32(out, uint32_t(value.size()));
    out += value;
}

}  // namespace hostile_detail

/// A PNG of `width` × `height` 8-bit RGB whose one IDAT holds a few bytes: 68 bytes, valid
/// CRCs, so a reader gets as far as allocating before it finds the data short.
inline std::string pngHeaderClaiming(uint32_t width, uint32_t height) {
    using namespace hostile_detail;
    std::string png("\x89PNG\r\n\x1a\n", 8), ihdr;
    putBigEndian32(ihdr, width);
    putBigEndian32(ihdr, height);
    ihdr +=
        std::string("\x08\x02\x00\x00\x00", 5);  // 8 bits, RGB, deflate, no filter, no interlace
    pngChunk(png, "IHDR", ihdr);
    pngChunk(png, "IDAT", std::string("\x78\x9c\x63\x00\x00\x00\x01\x00\x01", 9));
    pngChunk(png, "IEND", "");
    return png;
}

/// A baseline JPEG's markers up to its scan, claiming `width` × `height` (at most 65,535).
inline std::string jpegHeaderClaiming(uint16_t width, uint16_t height) {
    std::string j("\xFF\xD8", 2);
    j += std::string("\xFF\xDB\x00\x43\x00", 5) + std::string(64, '\x01');  // one quant table
    j += std::string("\xFF\xC0\x00\x0B\x08", 5);  // SOF0, 8 bits, one component
    j += char(height >> 8), j += char(height & 0xFF), j += char(width >> 8),
        j += char(width & 0xFF);
    j += std::string("\x01\x01\x11\x00", 4);
    j += std::string("\xFF\xDA\x00\x08\x01\x01\x00\x00\x3F\x00", 10);  // SOS
    j += std::string("\xFF\xD9", 2);
    return j;
}

/// A little-endian TIFF of one strip claiming `width` × `height` 8-bit grey.
inline std::string tiffHeaderClaiming(uint32_t width, uint32_t height) {
    using namespace hostile_detail;
    std::string t("II*\0", 4);
    putLittleEndian32(t, 8);
    const struct {
        uint16_t tag, type;
        uint32_t value;
    } entries[] = {{256, 4, width}, {257, 4, height}, {258, 3, 8},
                   {259, 3, 1},     {262, 3, 1},      {273, 4, 200},
                   {277, 3, 1},     {278, 4, height}, {279, 4, 0x7FFFFFFF}};
    putLittleEndian16(t, uint16_t(sizeof entries / sizeof entries[0]));
    for (const auto& e : entries) {
        putLittleEndian16(t, e.tag);
        putLittleEndian16(t, e.type);
        putLittleEndian32(t, 1);
        if (e.type == 3) {
            putLittleEndian16(t, uint16_t(e.value));
            putLittleEndian16(t, 0);
        } else {
            putLittleEndian32(t, e.value);
        }
    }
    putLittleEndian32(t, 0);  // no next IFD
    t.resize(256, '\0');
    return t;
}

/// A scan-line OpenEXR of one HALF channel "Y" whose data window is `width` × `height`, PIZ
/// compressed (32 lines a chunk, so the offset table is 8 bytes per 32 lines: 7.5 KB for
/// 30,000), every offset naming one empty chunk after the table.
inline std::string exrHeaderClaiming(uint32_t width, uint32_t height) {
    using namespace hostile_detail;
    std::string e("\x76\x2f\x31\x01\x02\x00\x00\x00", 8), channels("Y\0", 2), box, display;
    putLittleEndian32(channels, 1);    // HALF
    channels += std::string(4, '\0');  // pLinear, reserved
    putLittleEndian32(channels, 1);
    putLittleEndian32(channels, 1);
    channels += '\0';
    for (uint32_t v : {0u, 0u, width - 1, height - 1}) putLittleEndian32(box, v);
    exrAttribute(e, "channels", "chlist", channels);
    exrAttribute(e, "compression", "compression", std::string(1, '\x04'));
    exrAttribute(e, "dataWindow", "box2i", box);
    exrAttribute(e, "displayWindow", "box2i", box);
    exrAttribute(e, "lineOrder", "lineOrder", std::string(1, '\0'));
    exrAttribute(e, "pixelAspectRatio", "float", std::string("\x00\x00\x80\x3f", 4));
    exrAttribute(e, "screenWindowCenter", "v2f", std::string(8, '\0'));
    exrAttribute(e, "screenWindowWidth", "float", std::string("\x00\x00\x80\x3f", 4));
    e += '\0';
    const uint32_t chunks = (height + 31) / 32;
    const uint32_t chunkAt = uint32_t(e.size()) + 8 * chunks;
    for (uint32_t i = 0; i < chunks; ++i) {
        putLittleEndian32(e, chunkAt);
        putLittleEndian32(e, 0);
    }
    putLittleEndian32(e, 0);  // the chunk: line 0, no bytes
    putLittleEndian32(e, 0);
    return e;
}

}  // namespace kerf::test
