/// @file io/texture.cpp
/// @brief Opening textures through the image plug-in, with the file checked first.
#include "io/texture.h"

#include "io/image_plugin.h"
#include "io/image_plugin_loader.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>

namespace kerf {
namespace {

/// Why `path` cannot be a texture, or an empty string. By stat() alone, so a FIFO or a
/// device is refused without being opened (opening a FIFO would wait for a writer).
std::string fileProblem(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) {
        return errno == ENOENT ? std::string("no such file") : std::string(std::strerror(errno));
    }
    if (S_ISDIR(st.st_mode)) return "it is a folder, not an image";
    if (!S_ISREG(st.st_mode)) return "not a regular file";
    if (::access(path.c_str(), R_OK) != 0) return std::strerror(errno);
    return {};
}

/// The longest footprint axis passed on, in images: further, a repeating image is near its
/// mean along the axis anyway, and the plug-in's probes along it would only spread thinner.
constexpr double kLongestAxis = 16.0;

/// A footprint axis the plug-in can take: finite (a mapping's pole makes it infinite: then
/// the longest), and no longer than kLongestAxis, shortened along its own direction.
void limitAxis(double& ds, double& dt) {
    if (!std::isfinite(ds) || !std::isfinite(dt)) {
        ds = std::isfinite(ds) ? 0.0 : kLongestAxis;
        dt = std::isfinite(dt) ? 0.0 : kLongestAxis;
        return;
    }
    const double length = std::hypot(ds, dt);
    if (length > kLongestAxis) ds *= kLongestAxis / length, dt *= kLongestAxis / length;
}

/// A coordinate reduced to [0, 1) in double before it becomes a float, so far from the
/// origin a repeating texture keeps its texel precision; clamped ones keep their value.
float coordinate(double x, Texture::Wrap wrap) {
    if (!std::isfinite(x)) return 0.0f;
    if (wrap == Texture::Wrap::Clamp) return float(std::fmax(-1.0, std::fmin(2.0, x)));
    const double r = x - std::floor(x);
    return r < 1.0 ? float(r) : 0.0f;
}

int wrapCode(Texture::Wrap w) {
    return w == Texture::Wrap::Clamp ? KERF_TEXTURE_WRAP_CLAMP : KERF_TEXTURE_WRAP_PERIODIC;
}

}  // namespace

std::shared_ptr<const Texture> Texture::open(const std::string& path) {
    const std::string problem = fileProblem(path);
    if (!problem.empty()) throw TextureError(path, problem);
    const KerfImagePlugin& plugin = imagePlugin();
    KerfTexture* handle = nullptr;
    int width = 0, height = 0;
    char error[512] = "";
    if (plugin.textureOpen(path.c_str(), &handle, &width, &height, error, sizeof error) != 0 ||
        handle == nullptr)
        throw TextureError(path, error[0] ? error : "not an image");
    std::shared_ptr<Texture> texture(new Texture);
    texture->mPlugin = &plugin;
    texture->mHandle = handle;
    texture->mPath = path;
    texture->mWidth = width;
    texture->mHeight = height;
    return texture;
}

std::array<float, 3> Texture::lookup(double s, double t, double dsdx, double dtdx, double dsdy,
                                     double dtdy, Wrap wrapS, Wrap wrapT) const {
    std::array<float, 3> rgb{0.0f, 0.0f, 0.0f};
    limitAxis(dsdx, dtdx);
    limitAxis(dsdy, dtdy);
    mPlugin->textureLookup(mHandle, coordinate(s, wrapS), coordinate(t, wrapT), float(dsdx),
                           float(dtdx), float(dsdy), float(dtdy), wrapCode(wrapS), wrapCode(wrapT),
                           rgb.data());
    return rgb;
}

}  // namespace kerf
