/// @file io/plugin/oiio_image_plugin.cpp
/// @brief The image plug-in: OpenImageIO behind the C interface of io/image_plugin.h. Built as
/// a loadable module next to the kerf executable, so OpenImageIO and the ~260 libraries it
/// pulls in are loaded only by a process that reads or writes an image.
#include <OpenImageIO/imageio.h>

#include <cstdio>
#include <memory>
#include <string>

#include "io/image_plugin.h"

namespace {

int fail(const std::string& message, char* error, size_t errorSize) {
    if (errorSize > 0) std::snprintf(error, errorSize, "%s", message.c_str());
    return 1;
}

int writeImage(const char* path, int width, int height, int channels, int bytes, const void* pixels,
               const char* colorSpace, char* error, size_t errorSize) {
    try {
        std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path);
        if (!out) return fail(OIIO::geterror(), error, errorSize);
        const OIIO::TypeDesc type = bytes ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT;
        OIIO::ImageSpec spec(width, height, channels, type);
        spec.attribute("oiio:ColorSpace", colorSpace);
        if (!out->open(path, spec)) return fail(out->geterror(), error, errorSize);
        const bool ok = out->write_image(type, pixels);
        std::string message = ok ? "" : out->geterror();
        if (!out->close() && message.empty()) message = out->geterror();
        if (!ok && message.empty()) message = "write failed";
        return message.empty() ? 0 : fail(message, error, errorSize);
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

const KerfImagePlugin kPlugin = {KERF_IMAGE_PLUGIN_ABI, writeImage, readImage};

}  // namespace

extern "C" __attribute__((visibility("default"))) const KerfImagePlugin* kerf_image_plugin(void) {
    return &kPlugin;
}
