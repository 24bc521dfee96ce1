/// @file io/plugin/oiio_texture.cpp
/// @brief Image textures through OpenImageIO's TextureSystem. A file is decoded once and made
/// linear here (8- and 16-bit codes are sRGB, as kerf's own image reader takes them), because
/// the TextureSystem filters the values it is given: averaging sRGB codes would darken every
/// filtered region (the mean of codes 0 and 255 is 0.21 in light, not 0.5). The linear pixels
/// reach the TextureSystem's cache through a small in-memory ImageInput, and the cache builds
/// the MIP levels itself (`automip`).
#include "io/plugin/oiio_texture.h"

#include <OpenImageIO/imagecache.h>
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/texture.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

struct KerfTexture {
    OIIO::TextureSystem::TextureHandle* handle;
    int channels;  ///< 1 (grey) or 3 (RGB)
    int width, height;
};

namespace kerf_plugin {
namespace {

/// A texture's decoded linear pixels, 1 or 3 channels, top row first.
struct LinearPixels {
    int width = 0, height = 0, channels = 0;
    std::vector<float> values;
};

/// Everything the plug-in keeps for textures. Never destroyed: OpenImageIO's cache and its
/// threads live until the process ends, like the plug-in itself.
struct Textures {
    std::mutex mutex;        ///< held while opening; the cache calls LinearInput::open under it
    std::mutex pixelsMutex;  ///< guards byCacheName alone
    OIIO::ImageCache* cache = nullptr;
    OIIO::TextureSystem* system = nullptr;
    std::map<std::string, std::shared_ptr<const LinearPixels>> byCacheName;
    std::map<std::string, std::unique_ptr<KerfTexture>> byPath;
};

Textures& textures() {
    static Textures* t = new Textures;
    return *t;
}

/// Serves one texture's linear pixels to the cache, by the name it was added under.
class LinearInput final : public OIIO::ImageInput {
public:
    const char* format_name() const override { return "kerf-linear"; }
    bool open(const std::string& name, OIIO::ImageSpec& spec) override {
        {
            Textures& t = textures();
            std::lock_guard<std::mutex> lock(t.pixelsMutex);
            const auto it = t.byCacheName.find(name);
            if (it != t.byCacheName.end()) mPixels = it->second;
        }
        if (!mPixels) {
            errorfmt("no texture named {}", name);
            return false;
        }
        m_spec = OIIO::ImageSpec(mPixels->width, mPixels->height, mPixels->channels,
                                 OIIO::TypeDesc::FLOAT);
        spec = m_spec;
        return true;
    }
    bool close() override {
        mPixels.reset();
        return true;
    }
    bool seek_subimage(int subimage, int miplevel) override {
        return subimage == 0 && miplevel == 0;  // one level: the cache makes the others
    }
    bool read_native_scanline(int subimage, int miplevel, int y, int /*z*/, void* data) override {
        if (!mPixels || subimage != 0 || miplevel != 0 || y < 0 || y >= mPixels->height)
            return false;
        const size_t row = size_t(mPixels->width) * size_t(mPixels->channels);
        std::memcpy(data, mPixels->values.data() + size_t(y) * row, row * sizeof(float));
        return true;
    }

private:
    std::shared_ptr<const LinearPixels> mPixels;
};

OIIO::ImageInput* createLinearInput() { return new LinearInput; }

/// OpenImageIO's error text on one line: its lines (one per message it kept) joined by "; ",
/// so kerf's `file:line:col: error:` line stays one line.
std::string oneLine(const std::string& message) {
    std::string out;
    size_t start = 0;
    while (start <= message.size()) {
        const size_t end = std::min(message.find('\n', start), message.size());
        if (end > start) out += (out.empty() ? "" : "; ") + message.substr(start, end - start);
        start = end + 1;
    }
    return out;
}

int failWith(const std::string& message, char* error, size_t errorSize) {
    if (errorSize > 0) std::snprintf(error, errorSize, "%s", oneLine(message).c_str());
    return 1;
}

double srgbDecode(double encoded) {  // IEC 61966-2-1, as io/srgb.h
    return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

/// Why an image of this header cannot be a texture (too large, or not 2-D), or empty.
std::string headerProblem(const OIIO::ImageSpec& spec) {
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 || spec.depth > 1)
        return "not a two-dimensional image";
    const int64_t texels = int64_t(spec.width) * int64_t(spec.height);
    if (spec.width > KERF_TEXTURE_MAX_SIDE || spec.height > KERF_TEXTURE_MAX_SIDE ||
        texels > KERF_TEXTURE_MAX_TEXELS)
        return "its header says " + std::to_string(spec.width) + " x " +
               std::to_string(spec.height) + " pixels; a texture may have at most " +
               std::to_string(KERF_TEXTURE_MAX_SIDE) + " a side and " +
               std::to_string(KERF_TEXTURE_MAX_TEXELS) + " in all";
    return {};
}

/// Rows decoded at a time: the float copy of all the file's channels is one strip, never the
/// whole image.
constexpr int kTextureStripRows = 64;

/// Reads the image `in` has open into `out` (sized), made linear, strip by strip.
bool readLinearStrips(OIIO::ImageInput& in, bool integerCoded, LinearPixels& out,
                      std::string& why) {
    const size_t row = size_t(out.width) * size_t(out.channels);
    std::vector<float> strip(row * kTextureStripRows);
    for (int y0 = 0; y0 < out.height; y0 += kTextureStripRows) {
        const int y1 = std::min(out.height, y0 + kTextureStripRows);
        if (!in.read_scanlines(0, 0, y0, y1, 0, 0, out.channels, OIIO::TypeDesc::FLOAT,
                               strip.data())) {
            why = in.geterror();
            if (why.empty()) why = "its pixels cannot be read";
            return false;
        }
        float* const dst = out.values.data() + size_t(y0) * row;
        for (size_t i = 0; i < size_t(y1 - y0) * row; ++i) {
            const float v = strip[i];
            dst[i] = integerCoded ? float(srgbDecode(v)) : (std::isfinite(v) ? v : 0.0f);
        }
    }
    return true;
}

/// Decodes `path` into linear grey or RGB (alpha and other channels are dropped). The header
/// is checked against the texture limits before any pixel is allocated.
std::shared_ptr<LinearPixels> decode(const char* path, std::string& why) {
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
    if (!in) {
        why = OIIO::geterror();
        if (why.empty()) why = "not an image OpenImageIO can read";
        return nullptr;
    }
    const OIIO::ImageSpec spec = in->spec();
    why = headerProblem(spec);
    if (!why.empty()) return nullptr;
    auto out = std::make_shared<LinearPixels>();
    out->width = spec.width;
    out->height = spec.height;
    // Grey (with or without alpha) stays one channel; anything with three or more is RGB.
    out->channels = spec.nchannels >= 3 ? 3 : 1;
    const bool integerCoded = spec.format.basetype == OIIO::TypeDesc::UINT8 ||
                              spec.format.basetype == OIIO::TypeDesc::UINT16;
    out->values.resize(size_t(spec.width) * size_t(spec.height) * size_t(out->channels));
    if (!readLinearStrips(*in, integerCoded, *out, why)) return nullptr;
    in->close();
    return out;
}

void startSystem(Textures& t) {
    if (t.system) return;
    t.cache = OIIO::ImageCache::create(/*shared=*/false);
    t.cache->attribute("automip", 1);  // MIP levels for single-level images, made on demand
    t.system = OIIO::TextureSystem::create(/*shared=*/false, t.cache);
}

}  // namespace

int textureOpen(const char* path, KerfTexture** texture, int* width, int* height, char* error,
                size_t errorSize) {
    try {
        Textures& t = textures();
        {
            std::lock_guard<std::mutex> lock(t.mutex);
            const auto it = t.byPath.find(path);
            if (it != t.byPath.end()) {
                *texture = it->second.get();
                *width = it->second->width;
                *height = it->second->height;
                return 0;
            }
        }
        std::string why;
        std::shared_ptr<LinearPixels> pixels = decode(path, why);
        if (!pixels) return failWith(why, error, errorSize);
        std::lock_guard<std::mutex> lock(t.mutex);
        startSystem(t);
        // A name no file has, so the cache never looks on disk for it.
        std::string name;
        {
            std::lock_guard<std::mutex> pixelsLock(t.pixelsMutex);
            name = "kerf-texture-" + std::to_string(t.byCacheName.size()) + ".linear";
            t.byCacheName[name] = pixels;
        }
        const OIIO::ustring uname(name);
        if (!t.cache->add_file(uname, createLinearInput))
            return failWith(t.cache->geterror(), error, errorSize);
        OIIO::TextureSystem::TextureHandle* handle = t.system->get_texture_handle(uname);
        if (handle == nullptr || !t.system->good(handle)) {
            std::string message = t.system->geterror();
            return failWith(message.empty() ? "the texture system refused it" : message, error,
                            errorSize);
        }
        auto made = std::make_unique<KerfTexture>(
            KerfTexture{handle, pixels->channels, pixels->width, pixels->height});
        *texture = made.get();
        *width = pixels->width;
        *height = pixels->height;
        t.byPath[path] = std::move(made);
        return 0;
    } catch (const std::exception& e) {  // nothing may cross the C boundary
        return failWith(e.what(), error, errorSize);
    }
}

void textureLookup(const KerfTexture* texture, float s, float t, float dsdx, float dtdx, float dsdy,
                   float dtdy, int wrapS, int wrapT, float rgb[3]) {
    OIIO::TextureSystem* system = textures().system;
    // The calling thread's state, found once per thread: the TextureSystem's own lookup of it
    // goes through a thread-specific pointer on every call otherwise.
    thread_local OIIO::TextureSystem::Perthread* perthread = nullptr;
    if (perthread == nullptr) perthread = system->get_perthread_info();
    OIIO::TextureOpt options;
    const auto wrap = [](int w) {
        return w == KERF_TEXTURE_WRAP_CLAMP ? OIIO::TextureOpt::WrapClamp
                                            : OIIO::TextureOpt::WrapPeriodic;
    };
    options.swrap = wrap(wrapS);
    options.twrap = wrap(wrapT);
    // Bilinear within a level: it reproduces a texel at its centre (the default bicubic is a
    // B-spline, which blurs even there).
    options.interpmode = OIIO::TextureOpt::InterpBilinear;
    float result[3] = {0.0f, 0.0f, 0.0f};
    if (!system->texture(texture->handle, perthread, options, s, t, dsdx, dtdx, dsdy, dtdy,
                         texture->channels, result))
        result[0] = result[1] = result[2] = 0.0f;  // cannot happen for an opened texture
    if (texture->channels == 1) result[1] = result[2] = result[0];
    rgb[0] = result[0];
    rgb[1] = result[1];
    rgb[2] = result[2];
}

}  // namespace kerf_plugin
