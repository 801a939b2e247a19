// The scene's textures packed into the layers of one 2-D array image (vk/texture_array.h): each
// texture a rectangle of one layer. Mesa 22's lavapipe has no dynamic indexing of sampled-image
// arrays (shaderSampledImageArrayDynamicIndexing and descriptor indexing are false, at most 32
// samplers per stage), so one image per texture cannot be chosen per ray; one array image can,
// and is not bound by maxStorageBufferRange as the former texel buffer was. The shader reads texels
// with texelFetch and applies the glTF sampler's wrap and filter itself (shaders/render/scene_access.glsl).
// Textures the device cannot hold, or larger than --max-texture-size, are halved (2x2 box filter,
// in linear light for sRGB textures) with a warning. A texture some view samples with mipmaps
// (glTF minFilter) gets its chain of levels, made by the same filter, beside it in its rectangle
// (shared/texture_levels.glsl).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace vkp {

// What the atlas may use: the user's --max-texture-size and the device's image limits.
struct TextureLimits {
    uint32_t maxTextureSize = 0;         // --max-texture-size: largest width/height; 0: no limit
    uint32_t maxLayerSize = 16384;       // maxImageDimension2D (and the format's maxExtent)
    uint32_t maxLayers = 2048;           // maxImageArrayLayers
    uint64_t maxBytes = uint64_t(1) << 31;  // the image's bytes at most (memory, maxResourceSize)
};

struct TextureAtlasEntry {
    uint32_t x = 0, y = 0, layer = 0;    // the texture's top-left texel in the atlas
    uint32_t width = 0, height = 0;      // level 0's, after any downscaling
    uint32_t levels = 1;                 // mipmap levels in the rectangle (1: level 0 alone)
};

struct TextureAtlas {
    uint32_t width = 1, height = 1, layers = 1;   // every layer's size (1x1x1 when there are no textures)
    std::vector<TextureAtlasEntry> entries;       // one per Scene::textures entry
    std::vector<uint32_t> texels;                 // RGBA8, layer after layer, row-major; unused texels 0
    std::vector<std::string> downscaled;          // "name: WxH -> wxh (why)", one per downscaled texture
    uint64_t bytes() const { return uint64_t(width) * height * layers * 4; }
};

// Packs `textures` (shelves, tallest first) within `limits`, halving the largest texture until
// all fit; textures i with mipmapped[i] with their full chain of mipmap levels (a missing entry:
// none). Throws RuntimeError only if even 1x1 textures cannot fit (a device limit).
TextureAtlas buildTextureAtlas(const std::vector<Texture>& textures, const TextureLimits& limits,
                               const std::vector<bool>& mipmapped = {});

// --max-texture-size: halves every texture whose width or height exceeds maxSize (> 0) until it
// fits; returns "name: WxH -> wxh", one per downscaled texture.
std::vector<std::string> limitTextureSize(std::vector<Texture>& textures, uint32_t maxSize);

// --no-mipmaps: every texture view reads level 0 only, minified or not, with its magFilter (what
// vkphoton did before mipmaps: the many-spp reference, noisier at few).
void disableMipmaps(Scene& scene);

// One 2x2 box-filter halving (odd sizes: the last row/column repeats; sRGB textures averaged in
// linear light).
Texture halveTexture(const Texture& texture);

}  // namespace vkp
