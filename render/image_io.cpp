/// @file render/image_io.cpp
/// @brief Image files through OpenImageIO, written to a temporary file beside the target and
/// renamed onto it (render/atomic_file.h), so a failure never leaves a half file nor clobbers
/// an earlier one.
#include "render/image.h"

#include "render/atomic_file.h"
#include "render/srgb.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <memory>

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
std::string writeWithOiio(const Image& image, const std::string& file, Encoding encoding) {
    std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(file);
    if (!out) return OIIO::geterror();
    const bool bytes = encoding == Encoding::Srgb8;
    OIIO::ImageSpec spec(image.width, image.height, image.channels,
                         bytes ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT);
    spec.attribute("oiio:ColorSpace", bytes ? "sRGB" : "Linear");
    if (!out->open(file, spec)) return out->geterror();
    bool ok;
    if (bytes) {
        std::vector<uint8_t> codes(image.pixels.size());
        std::transform(image.pixels.begin(), image.pixels.end(), codes.begin(), srgbByte);
        ok = out->write_image(OIIO::TypeDesc::UINT8, codes.data());
    } else {
        ok = out->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data());
    }
    std::string error = ok ? "" : out->geterror();
    if (!out->close() && error.empty()) error = out->geterror();
    if (!ok && error.empty()) error = "write failed";
    return error;
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

    // The temporary keeps the real extension, so OpenImageIO picks the format from it.
    const std::string error =
        writeThroughTemporary(path, ext, [&](int, const std::string& temporary) {
            return writeWithOiio(image, temporary, encoding);
        });
    if (!error.empty()) fail(path, error);
}

Image readImage(const std::string& path) {
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
    if (!in) throw std::runtime_error("cannot read '" + path + "': " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    Image image(spec.width, spec.height, spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data()))
        throw std::runtime_error("cannot read '" + path + "': " + in->geterror());
    // Integer files hold sRGB codes (that is how writeImage stores them): back to linear.
    if (spec.format.basetype == OIIO::TypeDesc::UINT8 ||
        spec.format.basetype == OIIO::TypeDesc::UINT16)
        for (float& v : image.pixels) v = float(srgbDecode(v));
    in->close();
    return image;
}

}  // namespace kerf
