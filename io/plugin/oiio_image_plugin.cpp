/// @file io/plugin/oiio_image_plugin.cpp
/// @brief The image plug-in: OpenImageIO behind the C interface of io/image_plugin.h. Built as
/// a loadable module next to the kerf executable, so OpenImageIO and the ~260 libraries it
/// pulls in are loaded only by a process that reads or writes an image. It never writes to
/// disk: images are encoded in memory and kerf writes the bytes (io/atomic_file.h).
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "io/image_plugin.h"
#include "io/plugin/jpeg_errors.h"
#include "io/plugin/oiio_texture.h"

namespace {

int fail(const std::string& message, char* error, size_t errorSize) {
    if (errorSize > 0) std::snprintf(error, errorSize, "%s", message.c_str());
    return 1;
}

/// The arguments of KerfImagePlugin::encode, passed through runCatchingJpegErrors.
struct EncodeCall {
    const char* fileName;
    int width, height, channels, bytes;
    const void* pixels;
    const char* colorSpace;
    int x, y, fullWidth, fullHeight;  ///< where the image sits in the whole one
    KerfImageBytes sink;
    void* user;
    char* error;
    size_t errorSize;
};

int encodeUnguarded(void* data) {
    const EncodeCall& c = *static_cast<const EncodeCall*>(data);
    try {
        std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(c.fileName);
        if (!out) return fail(OIIO::geterror(), c.error, c.errorSize);
        if (!out->supports("ioproxy"))
            return fail(
                std::string("OpenImageIO cannot encode ") + out->format_name() + " in memory",
                c.error, c.errorSize);
        std::vector<unsigned char> encoded;
        OIIO::Filesystem::IOVecOutput proxy(encoded);
        const OIIO::TypeDesc type = c.bytes ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT;
        OIIO::ImageSpec spec(c.width, c.height, c.channels, type);
        spec.x = c.x;
        spec.y = c.y;
        spec.full_x = 0;
        spec.full_y = 0;
        spec.full_width = c.fullWidth;
        spec.full_height = c.fullHeight;
        spec.attribute("oiio:ColorSpace", c.colorSpace);
        if (c.channels == 2 || c.channels == 4) {
            // kerf's alpha is straight (a slice's colour is its materials' coverage-weighted
            // mean): without this OpenImageIO divides the colour by alpha as it writes.
            spec.alpha_channel = c.channels - 1;
            spec.attribute("oiio:UnassociatedAlpha", 1);
        }
        void* proxyPointer = &proxy;
        spec.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxyPointer);
        // Only the return values decide: geterror() can hold a warning after a success (the
        // TIFF writer reports Exif it could not write and still writes a good image).
        if (!out->open(c.fileName, spec)) return fail(out->geterror(), c.error, c.errorSize);
        const bool ok = out->write_image(type, c.pixels);
        std::string message = ok ? "" : out->geterror();
        if (!out->close() && message.empty()) message = out->geterror();
        if (!ok && message.empty()) message = "the encoder failed";
        if (message.empty() && encoded.empty()) message = "the encoder produced no bytes";
        if (!message.empty()) return fail(message, c.error, c.errorSize);
        if (c.sink(c.user, encoded.data(), encoded.size()) != 0)
            return fail("out of memory", c.error, c.errorSize);
        return 0;
    } catch (const std::exception& e) {  // nothing may cross the C boundary
        return fail(e.what(), c.error, c.errorSize);
    }
}

int encodeImageWindow(const char* fileName, int width, int height, int channels, int bytes,
                      const void* pixels, const char* colorSpace, int x, int y, int fullWidth,
                      int fullHeight, KerfImageBytes sink, void* user, char* error,
                      size_t errorSize) {
    EncodeCall call{fileName, width,     height,     channels, bytes, pixels, colorSpace, x,
                    y,        fullWidth, fullHeight, sink,     user,  error,  errorSize};
    // libjpeg would otherwise print its own message and exit (io/plugin/jpeg_errors.h).
    char jpegMessage[256] = "";
    const int result =
        kerf_plugin::runCatchingJpegErrors(encodeUnguarded, &call, jpegMessage, sizeof jpegMessage);
    if (result == -1) return fail(jpegMessage, error, errorSize);
    return result;
}

int encodeImage(const char* fileName, int width, int height, int channels, int bytes,
                const void* pixels, const char* colorSpace, KerfImageBytes sink, void* user,
                char* error, size_t errorSize) {
    return encodeImageWindow(fileName, width, height, channels, bytes, pixels, colorSpace, 0, 0,
                             width, height, sink, user, error, errorSize);
}

int readImageWindow(const char* path, KerfImageAllocate allocate, void* user, int window[4],
                    char* error, size_t errorSize) {
    try {
        // Straight alpha, as kerf writes it: OpenImageIO would multiply the colour by it.
        OIIO::ImageSpec config;
        config.attribute("oiio:UnassociatedAlpha", 1);
        std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path, &config);
        if (!in) return fail(OIIO::geterror(), error, errorSize);
        const OIIO::ImageSpec& spec = in->spec();
        const bool integerCoded = spec.format.basetype == OIIO::TypeDesc::UINT8 ||
                                  spec.format.basetype == OIIO::TypeDesc::UINT16;
        float* pixels = allocate(user, spec.width, spec.height, spec.nchannels, integerCoded);
        if (pixels == nullptr) return fail("no room for the pixels", error, errorSize);
        if (window != nullptr) {
            // Relative to the display window's corner (kerf writes it at 0, 0).
            window[0] = spec.x - spec.full_x;
            window[1] = spec.y - spec.full_y;
            window[2] = spec.full_width;
            window[3] = spec.full_height;
        }
        if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels))
            return fail(in->geterror(), error, errorSize);
        in->close();
        return 0;
    } catch (const std::exception& e) {
        return fail(e.what(), error, errorSize);
    }
}

int readImage(const char* path, KerfImageAllocate allocate, void* user, char* error,
              size_t errorSize) {
    return readImageWindow(path, allocate, user, nullptr, error, errorSize);
}

const KerfImagePlugin kPlugin = {
    KERF_IMAGE_PLUGIN_ABI,      encodeImage,       readImage,      kerf_plugin::textureOpen,
    kerf_plugin::textureLookup, encodeImageWindow, readImageWindow};

}  // namespace

extern "C" __attribute__((visibility("default"))) const KerfImagePlugin* kerf_image_plugin(void) {
    return &kPlugin;
}
