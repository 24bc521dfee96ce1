/// @file io/plugin/oiio_texture.h
/// @brief The texture half of the image plug-in (KerfImagePlugin::textureOpen and
/// textureLookup), over OpenImageIO's TextureSystem.
#pragma once

#include "io/image_plugin.h"

namespace kerf_plugin {

int textureOpen(const char* path, KerfTexture** texture, int* width, int* height, char* error,
                size_t errorSize);
void textureLookup(const KerfTexture* texture, float s, float t, float dsdx, float dtdx, float dsdy,
                   float dtdy, int wrapS, int wrapT, float rgb[3]);

}  // namespace kerf_plugin
