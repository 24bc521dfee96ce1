/// @file io/texture.h
/// @brief Image textures: an image file opened for filtered lookups through the image
/// plug-in's TextureSystem (io/image_plugin.h). Opening the first texture loads the plug-in;
/// a process that opens none never does.
#pragma once

#include <array>
#include <memory>
#include <stdexcept>
#include <string>

struct KerfImagePlugin;
struct KerfTexture;

namespace kerf {

/// Thrown when a texture cannot be opened; what() is "cannot read texture 'PATH': REASON".
struct TextureError : std::runtime_error {
    TextureError(const std::string& path, const std::string& reason)
        : std::runtime_error("cannot read texture '" + path + "': " + reason), reason(reason) {}
    std::string reason;  ///< why, without the file name
};

class Texture {
public:
    /// How a coordinate outside [0, 1) is taken: the image repeats, or its edge is extended.
    enum class Wrap { Periodic, Clamp };

    /// Opens the image at `path` (any format OpenImageIO reads; 8- and 16-bit codes are sRGB
    /// and made linear). The same path opened twice shares the plug-in's texture. Throws
    /// TextureError when the file is missing, not a regular file, unreadable or not an image
    /// (checked before the plug-in sees it, so a FIFO is never opened), and ImageSupportError
    /// when the plug-in cannot be loaded.
    static std::shared_ptr<const Texture> open(const std::string& path);

    const std::string& path() const { return mPath; }
    int width() const { return mWidth; }
    int height() const { return mHeight; }

    /// Linear RGB filtered over the footprint centred at (s, t) whose two axes in texture space
    /// are (dsdx, dtdx) and (dsdy, dtdy) (full widths, as a pixel's derivatives). s runs
    /// across the image, t down from its top row; texel (i, j) has its centre at
    /// ((i + ½)/width, (j + ½)/height). MIP-mapped, anisotropic; a zero footprint still gets
    /// the bilinear filter of the texels (never a point sample). Thread-safe.
    std::array<float, 3> lookup(double s, double t, double dsdx, double dtdx, double dsdy,
                                double dtdy, Wrap wrapS = Wrap::Periodic,
                                Wrap wrapT = Wrap::Periodic) const;

private:
    Texture() = default;
    const KerfImagePlugin* mPlugin = nullptr;
    const KerfTexture* mHandle = nullptr;  ///< owned by the plug-in, valid to the process's end
    std::string mPath;
    int mWidth = 0, mHeight = 0;
};

}  // namespace kerf
