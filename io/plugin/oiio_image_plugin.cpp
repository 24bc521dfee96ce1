/// @file io/plugin/oiio_image_plugin.cpp
/// @brief The image plug-in: OpenImageIO behind the C interface of io/image_plugin.h. Built as
/// a loadable module next to the kerf executable, so OpenImageIO and the ~260 libraries it
/// pulls in are loaded only by a process that reads or writes an image. It never writes to
/// disk: images are encoded in memory and kerf writes the bytes (io/atomic_file.h).
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <cctype>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "io/image_plugin.h"

namespace {

int fail(const std::string& message, char* error, size_t errorSize) {
    if (errorSize > 0) std::snprintf(error, errorSize, "%s", message.c_str());
    return 1;
}

/// libjpeg's default error handler prints its own message and exits the process; kerf's
/// checks keep it from being reached: the largest size JPEG can hold is tested here, and the
/// bytes go to memory, where no write can fail.
constexpr int kJpegMaxSide = 65500;

bool isJpeg(const std::string& fileName) {
    const size_t dot = fileName.find_last_of('.');
    std::string ext = dot == std::string::npos ? "" : fileName.substr(dot + 1);
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext == "jpg" || ext == "jpeg" || ext == "jpe";
}

int encodeImage(const char* fileName, int width, int height, int channels, int bytes,
                const void* pixels, const char* colorSpace, KerfImageBytes sink, void* user,
                char* error, size_t errorSize) {
    try {
        if (isJpeg(fileName) && (width > kJpegMaxSide || height > kJpegMaxSide))
            return fail("a JPEG image is at most " + std::to_string(kJpegMaxSide) +
                            " pixels wide and high",
                        error, errorSize);
        std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(fileName);
        if (!out) return fail(OIIO::geterror(), error, errorSize);
        if (!out->supports("ioproxy"))
            return fail(std::string("OpenImageIO cannot encode ") + out->format_name() +
                            " in memory",
                        error, errorSize);
        std::vector<unsigned char> encoded;
        OIIO::Filesystem::IOVecOutput proxy(encoded);
        const OIIO::TypeDesc type = bytes ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT;
        OIIO::ImageSpec spec(width, height, channels, type);
        spec.attribute("oiio:ColorSpace", colorSpace);
        void* proxyPointer = &proxy;
        spec.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxyPointer);
        // Only the return values decide: geterror() can hold a warning after a success (the
        // TIFF writer reports Exif it could not write and still writes a good image).
        if (!out->open(fileName, spec)) return fail(out->geterror(), error, errorSize);
        const bool ok = out->write_image(type, pixels);
        std::string message = ok ? "" : out->geterror();
        if (!out->close() && message.empty()) message = out->geterror();
        if (!ok && message.empty()) message = "the encoder failed";
        if (message.empty() && encoded.empty()) message = "the encoder produced no bytes";
        if (!message.empty()) return fail(message, error, errorSize);
        if (sink(user, encoded.data(), encoded.size()) != 0)
            return fail("out of memory", error, errorSize);
        return 0;
    } catch (const std::exception& e) {  // nothing may cross the C boundary
        return fail(e.what(), error, errorSize);
    }
}

int readImage(const char* path, KerfImageAllocate allocate, void* user, char* error,
              size_t errorSize) {
    try {
        std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
        if (!in) return fail(OIIO::geterror(), error, errorSize);
        const OIIO::ImageSpec& spec = in->spec();
        const bool integerCoded = spec.format.basetype == OIIO::TypeDesc::UINT8 ||
                                  spec.format.basetype == OIIO::TypeDesc::UINT16;
        float* pixels = allocate(user, spec.width, spec.height, spec.nchannels, integerCoded);
        if (pixels == nullptr) return fail("no room for the pixels", error, errorSize);
        if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels))
            return fail(in->geterror(), error, errorSize);
        in->close();
        return 0;
    } catch (const std::exception& e) {
        return fail(e.what(), error, errorSize);
    }
}

const KerfImagePlugin kPlugin = {KERF_IMAGE_PLUGIN_ABI, encodeImage, readImage};

}  // namespace

extern "C" __attribute__((visibility("default"))) const KerfImagePlugin* kerf_image_plugin(void) {
    return &kPlugin;
}
