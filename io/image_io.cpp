/// @file io/image_io.cpp
/// @brief Image files through the image plug-in (OpenImageIO, loaded on first use), which
/// encodes them in memory (a whole PNG through libpng here, with no plug-in); the bytes are written
/// by the one checked write path (io/atomic_file.h), so a failure never leaves a half file nor
/// clobbers an earlier one. The sRGB coding is done here, so the plug-in only moves buffers.
#include "io/image.h"

#include "io/atomic_file.h"
#include "io/file_checks.h"
#include "io/image_plugin_loader.h"
#include "io/png_write.h"
#include "io/srgb.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <vector>

namespace kerf {
namespace {

enum class Encoding { Srgb8, LinearFloat, Unknown };

std::string lowercaseExtension(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    const size_t dot = path.find_last_of('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
    std::string ext = path.substr(dot);
    for (char& ch : ext) ch = char(std::tolower(static_cast<unsigned char>(ch)));
    return ext;
}

Encoding encodingFor(const std::string& ext) {
    if (ext == ".png" || ext == ".jpg" || ext == ".jpeg") return Encoding::Srgb8;
    if (ext == ".exr" || ext == ".tif" || ext == ".tiff") return Encoding::LinearFloat;
    return Encoding::Unknown;
}

[[noreturn]] void fail(const std::string& path, const std::string& reason) {
    throw ImageWriteError(cannotWrite(path, reason));
}

/// Whether channel `c` of an image of `channels` is alpha (grey + alpha, RGBA).
bool isAlpha(int c, int channels) { return (channels == 2 || channels == 4) && c == channels - 1; }

/// The 8-bit codes of `image`: colour as sRGB, alpha linear (PNG and JPEG store alpha as
/// coverage, not light).
std::vector<uint8_t> eightBitCodes(const Image& image) {
    std::vector<uint8_t> codes(image.pixels.size());
    const int n = image.channels;
    for (size_t k = 0; k < codes.size(); ++k) {
        const float v = image.pixels[k];
        codes[k] =
            isAlpha(int(k % size_t(n)), n)
                ? uint8_t(std::lround(std::clamp(std::isnan(v) ? 0.0f : v, 0.0f, 1.0f) * 255.0f))
                : srgbByte(v);
    }
    return codes;
}

/// Takes the encoded file from the plug-in (a C callback: nothing may be thrown through it).
int keepBytes(void* user, const void* data, size_t size) {
    try {
        auto* bytes = static_cast<std::string*>(user);
        bytes->assign(static_cast<const char*>(data), size);
        return 0;
    } catch (...) {
        return 1;
    }
}

/// Encodes `image` in the format `path`'s extension names into `bytes`; "" or the reason.
std::string encode(const KerfImagePlugin& plugin, const Image& image, const std::string& path,
                   Encoding encoding, const ImageWindow& w, std::string& bytes) {
    char error[1024] = "";
    int failed;
    if (encoding == Encoding::Srgb8) {
        const std::vector<uint8_t> codes = eightBitCodes(image);
        failed = plugin.encodeWindow(path.c_str(), image.width, image.height, image.channels, 1,
                                     codes.data(), "sRGB", w.x, w.y, w.fullWidth, w.fullHeight,
                                     keepBytes, &bytes, error, sizeof error);
    } else {
        failed = plugin.encodeWindow(path.c_str(), image.width, image.height, image.channels, 0,
                                     image.pixels.data(), "Linear", w.x, w.y, w.fullWidth,
                                     w.fullHeight, keepBytes, &bytes, error, sizeof error);
    }
    if (!failed) return "";
    return error[0] != 0 ? std::string(error) : std::string("the encoder failed");
}

/// Where the plug-in reads into: the image, sized once the file's size is known.
struct ReadTarget {
    Image image;
    bool integerCoded = false;
};

float* allocateFor(void* user, int width, int height, int channels, int integerCoded) {
    if (width <= 0 || height <= 0 || channels <= 0) return nullptr;
    auto* target = static_cast<ReadTarget*>(user);
    target->image = Image(width, height, channels);
    target->integerCoded = integerCoded != 0;
    return target->image.pixels.data();
}

}  // namespace

void writeImage(const Image& image, const std::string& path) {
    writeImage(image, path, ImageWindow{0, 0, image.width, image.height});
}

void writeImage(const Image& image, const std::string& path, const ImageWindow& window) {
    const std::string ext = lowercaseExtension(path);
    const Encoding encoding = encodingFor(ext);
    if (encoding == Encoding::Unknown)
        fail(path,
             "unknown image format '" + ext + "' (use .png, .jpg, .jpeg, .exr, .tif or .tiff)");
    if (image.width <= 0 || image.height <= 0 || image.channels <= 0 ||
        image.pixels.size() != size_t(image.width) * image.height * image.channels)
        fail(path, "the image is empty or its pixel buffer does not match its size");
    if (window.x < 0 || window.y < 0 || window.x + image.width > window.fullWidth ||
        window.y + image.height > window.fullHeight)
        fail(path, "the image does not fit inside its full image");

    // JPEG's own limit, checked here rather than left to libjpeg: its error would be caught (the
    // plug-in turns it into a message), but only by a longjmp past OpenImageIO's cleanup.
    constexpr int kJpegMaxSide = 65500;
    if ((ext == ".jpg" || ext == ".jpeg") &&
        (image.width > kJpegMaxSide || image.height > kJpegMaxSide))
        fail(path, "JPEG images are at most " + std::to_string(kJpegMaxSide) +
                       " pixels wide and high (use .png, .exr or .tif)");
    // A folder that is missing or not writable is reported as such, before encoding.
    const std::string problem = outputProblem(path, false);
    if (!problem.empty()) fail(path, problem);
    std::string bytes;
    // A whole PNG is libpng's alone (io/png_write.h); a window of a larger image keeps the
    // plug-in, which records the window as OpenImageIO reads it back. Alpha is straight in
    // both, as PNG defines it.
    const bool whole = window.x == 0 && window.y == 0 && window.fullWidth == image.width &&
                       window.fullHeight == image.height;
    std::string error;
    if (ext == ".png" && whole) {
        const std::vector<uint8_t> codes = eightBitCodes(image);
        error = encodePngSrgb8(codes.data(), image.width, image.height, image.channels, bytes);
    } else {
        error = encode(imagePlugin(), image, path, encoding, window, bytes);
    }
    if (!error.empty()) fail(path, error);
    // The temporary keeps the real extension, so a tool looking at it sees what it is.
    const std::string writeError = replaceFile(path, ext, bytes.data(), bytes.size());
    if (!writeError.empty()) fail(path, writeError);
}

Image readImage(const std::string& path) {
    ImageWindow window;
    return readImage(path, window);
}

Image readImage(const std::string& path, ImageWindow& window) {
    // Before the plug-in opens it: OpenImageIO would wait on a FIFO and read /dev/zero for ever.
    if (const std::string problem = readableFileProblem(path); !problem.empty())
        throw std::runtime_error("cannot read '" + path + "': " + problem);
    const KerfImagePlugin& plugin = imagePlugin();
    ReadTarget target;
    char error[1024] = "";
    int w[4] = {0, 0, 0, 0};
    if (plugin.readWindow(path.c_str(), allocateFor, &target, w, error, sizeof error) != 0)
        throw std::runtime_error("cannot read '" + path + "': " + error);
    window = ImageWindow{w[0], w[1], w[2], w[3]};
    // Integer files hold sRGB codes (that is how writeImage stores them): back to linear; alpha
    // is linear already.
    if (target.integerCoded) {
        const int n = target.image.channels;
        for (size_t k = 0; k < target.image.pixels.size(); ++k)
            if (!isAlpha(int(k % size_t(n)), n))
                target.image.pixels[k] = float(srgbDecode(target.image.pixels[k]));
    }
    return std::move(target.image);
}

}  // namespace kerf
