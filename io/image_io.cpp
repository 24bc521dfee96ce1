/// @file io/image_io.cpp
/// @brief Image files through the image plug-in (OpenImageIO, loaded on first use), written
/// to a temporary file beside the target and renamed onto it (io/atomic_file.h), so a failure
/// never leaves a half file nor clobbers an earlier one. The sRGB coding is done here, so the
/// plug-in only moves buffers.
#include "io/image.h"

#include "io/atomic_file.h"
#include "io/image_plugin_loader.h"
#include "io/srgb.h"

#include <algorithm>
#include <cctype>
#include <cstdint>

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
    throw ImageWriteError("cannot write '" + path + "': " + reason);
}

/// Writes `image` to `file` (format by extension); returns an error message or "".
std::string writeWithPlugin(const KerfImagePlugin& plugin, const Image& image,
                            const std::string& file, Encoding encoding) {
    char error[1024] = "";
    int failed;
    if (encoding == Encoding::Srgb8) {
        std::vector<uint8_t> codes(image.pixels.size());
        std::transform(image.pixels.begin(), image.pixels.end(), codes.begin(), srgbByte);
        failed = plugin.write(file.c_str(), image.width, image.height, image.channels, 1,
                              codes.data(), "sRGB", error, sizeof error);
    } else {
        failed = plugin.write(file.c_str(), image.width, image.height, image.channels, 0,
                              image.pixels.data(), "Linear", error, sizeof error);
    }
    if (!failed) return "";
    return error[0] != 0 ? std::string(error) : std::string("write failed");
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
    const std::string ext = lowercaseExtension(path);
    const Encoding encoding = encodingFor(ext);
    if (encoding == Encoding::Unknown)
        fail(path, "unknown image format '" + ext + "' (use .png, .jpg, .jpeg, .exr, .tif or .tiff)");
    if (image.width <= 0 || image.height <= 0 || image.channels <= 0 ||
        image.pixels.size() != size_t(image.width) * image.height * image.channels)
        fail(path, "the image is empty or its pixel buffer does not match its size");

    const KerfImagePlugin& plugin = imagePlugin();
    // The temporary keeps the real extension, so OpenImageIO picks the format from it.
    const std::string error =
        writeThroughTemporary(path, ext, [&](int, const std::string& temporary) {
            return writeWithPlugin(plugin, image, temporary, encoding);
        });
    if (!error.empty()) fail(path, error);
}

Image readImage(const std::string& path) {
    const KerfImagePlugin& plugin = imagePlugin();
    ReadTarget target;
    char error[1024] = "";
    if (plugin.read(path.c_str(), allocateFor, &target, error, sizeof error) != 0)
        throw std::runtime_error("cannot read '" + path + "': " + error);
    // Integer files hold sRGB codes (that is how writeImage stores them): back to linear.
    if (target.integerCoded)
        for (float& v : target.image.pixels) v = float(srgbDecode(v));
    return std::move(target.image);
}

}  // namespace kerf
