/// @file io/png_write.cpp
/// @brief PNG encoding through libpng (io/png_write.h).
#include "io/png_write.h"

#include <png.h>

#include <cstring>
#include <vector>

namespace kerf {
namespace {

/// The state libpng's callbacks reach through its error and io pointers.
struct PngSink {
    std::string* bytes;
    char message[256] = "";
};

void pngFailure(png_structp png, png_const_charp message) {
    auto* sink = static_cast<PngSink*>(png_get_error_ptr(png));
    std::strncpy(sink->message, message, sizeof sink->message - 1);
    png_longjmp(png, 1);
}

void pngWarning(png_structp, png_const_charp) {}  // nothing libpng warns of here matters

void pngAppend(png_structp png, png_bytep data, size_t size) {
    auto* sink = static_cast<PngSink*>(png_get_io_ptr(png));
    try {
        sink->bytes->append(reinterpret_cast<const char*>(data), size);
    } catch (...) {  // nothing may be thrown through libpng's C frames
        png_error(png, "out of memory for the encoded image");
    }
}

void pngFlush(png_structp) {}

int colorTypeFor(int channels) {
    switch (channels) {
        case 1: return PNG_COLOR_TYPE_GRAY;
        case 2: return PNG_COLOR_TYPE_GRAY_ALPHA;
        case 3: return PNG_COLOR_TYPE_RGB;
        default: return PNG_COLOR_TYPE_RGB_ALPHA;
    }
}

/// The libpng calls; false after a libpng error (the reason in sink.message). Only C data and
/// pointers made before the setjmp live in this frame, so the longjmp skips no destructor.
bool writePng(png_structp png, png_infop info, const uint8_t* codes, int width, int height,
              int channels, png_bytep* rows) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), 8, colorTypeFor(channels),
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    png_write_info(png, info);
    for (int y = 0; y < height; ++y)
        rows[y] = const_cast<png_bytep>(codes + size_t(y) * size_t(width) * size_t(channels));
    png_write_image(png, rows);
    png_write_end(png, nullptr);
    return true;
}

}  // namespace

std::string encodePngSrgb8(const uint8_t* codes, int width, int height, int channels,
                           std::string& bytes) {
    if (width <= 0 || height <= 0 || channels < 1 || channels > 4)
        return "PNG holds 1 to 4 channels of a non-empty image";
    std::vector<png_bytep> rows(static_cast<size_t>(height));
    PngSink sink{&bytes};
    bytes.clear();
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &sink, pngFailure, pngWarning);
    if (png == nullptr) return "libpng could not start an encoder";
    // Again after the struct exists: io/png_errors_quiet.cpp keeps the handler by struct.
    png_set_error_fn(png, &sink, pngFailure, pngWarning);
    png_infop info = png_create_info_struct(png);
    if (info == nullptr) {
        png_destroy_write_struct(&png, nullptr);
        return "libpng could not start an encoder";
    }
    png_set_user_limits(png, 0x7fffffff, 0x7fffffff);  // PNG's own; libpng's default is 10^6
    png_set_write_fn(png, &sink, pngAppend, pngFlush);
    const bool written = writePng(png, info, codes, width, height, channels, rows.data());
    png_destroy_write_struct(&png, &info);
    if (written) return "";
    bytes.clear();
    return std::string("PNG encoding failed: ") + sink.message;
}

}  // namespace kerf
