#include "gpu_scene/texture_atlas.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

#include <fmt/format.h>

#include "shared/texture_levels.glsl"
#include "util/errors.h"

namespace vkp {
namespace {

float srgbToLinear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }
float linearToSrgb(float c) { return c <= 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f; }

const std::array<float, 256>& srgbTable() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int i = 0; i < 256; ++i) t[i] = srgbToLinear(float(i) / 255.0f);
        return t;
    }();
    return table;
}

uint32_t toByte(float v) { return static_cast<uint32_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }

// Next-fit shelf packing of `sizes` into layers of width x height; false when a size exceeds the
// layer or more than maxLayers layers are needed.
bool pack(const std::vector<TextureAtlasEntry>& sizes, uint32_t width, uint32_t height, uint32_t maxLayers,
          std::vector<TextureAtlasEntry>& out, uint32_t& layers) {
    std::vector<size_t> order(sizes.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return sizes[a].height > sizes[b].height; });
    out = sizes;
    uint32_t x = 0, y = 0, shelf = 0, layer = 0;
    for (size_t i : order) {
        const uint32_t w = sizes[i].width, h = sizes[i].height;
        if (w > width || h > height) return false;
        if (x + w > width) { x = 0; y += shelf; shelf = 0; }
        if (y + h > height) { x = 0; y = 0; shelf = 0; ++layer; }
        out[i].x = x;
        out[i].y = y;
        out[i].layer = layer;
        x += w;
        shelf = std::max(shelf, h);
    }
    layers = layer + 1;
    return layers <= maxLayers;
}

}  // namespace

Texture halveTexture(const Texture& t) {
    Texture out;
    out.name = t.name;
    out.srgb = t.srgb;
    out.width = std::max(1u, (t.width + 1) / 2);
    out.height = std::max(1u, (t.height + 1) / 2);
    out.rgba8.resize(size_t(out.width) * out.height);
    const auto& table = srgbTable();
    for (uint32_t y = 0; y < out.height; ++y)
        for (uint32_t x = 0; x < out.width; ++x) {
            std::array<float, 4> sum{};
            for (uint32_t dy = 0; dy < 2; ++dy)
                for (uint32_t dx = 0; dx < 2; ++dx) {
                    const uint32_t sx = std::min(2 * x + dx, t.width - 1), sy = std::min(2 * y + dy, t.height - 1);
                    const uint32_t p = t.rgba8[size_t(sy) * t.width + sx];
                    for (int c = 0; c < 4; ++c) {
                        const uint32_t byte = (p >> (8 * c)) & 0xffu;
                        sum[c] += (t.srgb && c < 3) ? table[byte] : float(byte) / 255.0f;
                    }
                }
            uint32_t packed = 0;
            for (int c = 0; c < 4; ++c) {
                const float mean = 0.25f * sum[c];
                packed |= toByte((t.srgb && c < 3) ? linearToSrgb(mean) : mean) << (8 * c);
            }
            out.rgba8[size_t(y) * out.width + x] = packed;
        }
    return out;
}

std::vector<std::string> limitTextureSize(std::vector<Texture>& textures, uint32_t maxSize) {
    std::vector<std::string> out;
    if (maxSize == 0) return out;
    for (Texture& t : textures) {
        const uint32_t width = t.width, height = t.height;
        while (std::max(t.width, t.height) > maxSize) t = halveTexture(t);
        if (t.width != width || t.height != height)
            out.push_back(fmt::format("{}: {}x{} -> {}x{}", t.name, width, height, t.width, t.height));
    }
    return out;
}

namespace {

// Copies t's texels into the atlas layer (width `atlasWidth`) at (x, y).
void copyTexels(const Texture& t, uint32_t* layer, uint32_t atlasWidth, uint32_t x, uint32_t y) {
    for (uint32_t row = 0; row < t.height; ++row)
        std::copy_n(t.rgba8.data() + size_t(row) * t.width, t.width, layer + size_t(y + row) * atlasWidth + x);
}

}  // namespace

void disableMipmaps(Scene& scene) {
    for (TextureView& view : scene.textureViews) {
        view.mipmaps = MipmapMode::None;
        view.minNearest = view.nearest;
    }
}

TextureAtlas buildTextureAtlas(const std::vector<Texture>& textures, const TextureLimits& limits,
                               const std::vector<bool>& mipmapped) {
    TextureAtlas atlas;
    if (textures.empty()) {
        atlas.texels.assign(1, 0u);
        return atlas;
    }
    // Downscaled copies only where needed; index -> the texture actually packed.
    std::vector<Texture> scaled(textures.size());
    std::vector<bool> isScaled(textures.size(), false);
    std::vector<std::string> reason(textures.size());
    auto current = [&](size_t i) -> const Texture& { return isScaled[i] ? scaled[i] : textures[i]; };
    // The rectangle texture i takes: level 0, and its mipmap levels where it has them.
    auto levels = [&](size_t i) {
        const bool chain = i < mipmapped.size() && mipmapped[i];
        return chain ? gpu::mipLevelCount(current(i).width, current(i).height) : 1u;
    };
    auto rectWidth = [&](size_t i) { return gpu::mipRectWidth(current(i).width, levels(i)); };
    auto rectHeight = [&](size_t i) { return gpu::mipRectHeight(current(i).height, levels(i)); };
    auto halve = [&](size_t i, const std::string& why) {
        scaled[i] = halveTexture(current(i));
        isScaled[i] = true;
        if (reason[i].empty()) reason[i] = why;
    };
    const uint32_t userMax = limits.maxTextureSize;
    for (size_t i = 0; i < textures.size(); ++i) {
        while (userMax > 0 && std::max(current(i).width, current(i).height) > userMax &&
               std::max(current(i).width, current(i).height) > 1)
            halve(i, fmt::format("--max-texture-size {}", userMax));
        while (std::max(rectWidth(i), rectHeight(i)) > limits.maxLayerSize &&
               std::max(current(i).width, current(i).height) > 1)
            halve(i, fmt::format("the device's largest image is {0}x{0}", limits.maxLayerSize));
    }
    const std::string budget = limits.maxBytes >= (uint64_t(1) << 20) ? fmt::format("{} MiB", limits.maxBytes >> 20)
                                                                         : fmt::format("{} bytes", limits.maxBytes);
    const std::string deviceReason = fmt::format("the device holds at most {} of textures in {} layers of at most {}x{}",
                                                 budget, limits.maxLayers, limits.maxLayerSize, limits.maxLayerSize);
    for (;;) {
        std::vector<TextureAtlasEntry> sizes(textures.size());
        uint32_t width = 1, height = 1;
        for (size_t i = 0; i < textures.size(); ++i) {
            sizes[i].width = rectWidth(i);
            sizes[i].height = rectHeight(i);
            width = std::max(width, sizes[i].width);
            height = std::max(height, sizes[i].height);
        }
        // Layers as large as the largest texture; larger ones (up to maxLayerSize) when that needs
        // more than maxLayers of them.
        bool fits = false;
        for (;;) {
            uint32_t layers = 0;
            const bool packed = pack(sizes, width, height, limits.maxLayers, atlas.entries, layers);
            if (packed && uint64_t(width) * height * layers * 4 <= limits.maxBytes) {
                atlas.width = width;
                atlas.height = height;
                atlas.layers = layers;
                fits = true;
                break;
            }
            if (packed || (width >= limits.maxLayerSize && height >= limits.maxLayerSize)) break;
            uint32_t& grow = width <= height ? width : height;
            grow = std::min(limits.maxLayerSize, grow * 2);
        }
        if (fits) break;
        // The largest texture (by area) loses half its width and height.
        size_t largest = 0;
        for (size_t i = 1; i < textures.size(); ++i)
            if (uint64_t(rectWidth(i)) * rectHeight(i) > uint64_t(rectWidth(largest)) * rectHeight(largest))
                largest = i;
        if (current(largest).width <= 1 && current(largest).height <= 1)
            throw RuntimeError(fmt::format("{} textures do not fit: {}", textures.size(), deviceReason));
        halve(largest, deviceReason);
    }
    atlas.texels.assign(atlas.bytes() / 4, 0u);
    for (size_t i = 0; i < textures.size(); ++i) {
        const Texture& t = current(i);
        TextureAtlasEntry& e = atlas.entries[i];
        e.width = t.width;  // level 0 (pack() sized the entry as the whole rectangle)
        e.height = t.height;
        e.levels = levels(i);
        uint32_t* layer = atlas.texels.data() + size_t(e.layer) * atlas.width * atlas.height;
        copyTexels(t, layer, atlas.width, e.x, e.y);
        Texture level;
        for (uint32_t l = 1; l < e.levels; ++l) {
            level = halveTexture(l == 1 ? t : level);
            copyTexels(level, layer, atlas.width, e.x + gpu::mipLevelColumn(t.width, l), e.y + gpu::mipLevelRow(t.height, l));
        }
        if (isScaled[i])
            atlas.downscaled.push_back(fmt::format("{}: {}x{} -> {}x{} ({})", textures[i].name, textures[i].width,
                                                   textures[i].height, t.width, t.height, reason[i]));
    }
    return atlas;
}

}  // namespace vkp
