// The texture atlas (gpu_scene/texture_atlas.h): packing keeps every texel, downscaling to
// --max-texture-size or to the device's limits halves with a 2x2 box filter (known texels), and
// never refuses a scene that 1x1 textures would fit.
#include <gtest/gtest.h>

#include <cmath>

#include "gpu_scene/texture_atlas.h"
#include "shared/texture_levels.glsl"

namespace vkp {
namespace {

Texture makeTexture(const std::string& name, uint32_t width, uint32_t height, uint32_t seed, bool srgb = false) {
    Texture t;
    t.name = name;
    t.width = width;
    t.height = height;
    t.srgb = srgb;
    t.rgba8.resize(size_t(width) * height);
    uint32_t h = seed * 2654435761u + 1u;
    for (uint32_t& p : t.rgba8) {
        h ^= h << 13;
        h ^= h >> 17;
        h ^= h << 5;
        p = h;
    }
    return t;
}

uint32_t atlasTexel(const TextureAtlas& a, size_t texture, uint32_t x, uint32_t y) {
    const TextureAtlasEntry& e = a.entries[texture];
    return a.texels[(size_t(e.layer) * a.height + e.y + y) * a.width + e.x + x];
}

TEST(TextureAtlas, PackingKeepsEveryTexelAndNoTwoTexturesOverlap) {
    std::vector<Texture> textures;
    const uint32_t sizes[][2] = {{64, 64}, {16, 48}, {33, 7}, {64, 1}, {1, 1}, {50, 64}, {8, 8}, {64, 30}};
    for (uint32_t i = 0; i < 8; ++i) textures.push_back(makeTexture("t" + std::to_string(i), sizes[i][0], sizes[i][1], i));
    const TextureAtlas a = buildTextureAtlas(textures, {});
    ASSERT_EQ(a.entries.size(), textures.size());
    EXPECT_TRUE(a.downscaled.empty());
    std::vector<int> owner(size_t(a.width) * a.height * a.layers, -1);
    for (size_t i = 0; i < textures.size(); ++i) {
        const TextureAtlasEntry& e = a.entries[i];
        ASSERT_EQ(e.width, textures[i].width);
        ASSERT_EQ(e.height, textures[i].height);
        ASSERT_LT(e.layer, a.layers);
        ASSERT_LE(e.x + e.width, a.width);
        ASSERT_LE(e.y + e.height, a.height);
        for (uint32_t y = 0; y < e.height; ++y)
            for (uint32_t x = 0; x < e.width; ++x) {
                ASSERT_EQ(atlasTexel(a, i, x, y), textures[i].rgba8[size_t(y) * e.width + x]) << textures[i].name;
                int& o = owner[(size_t(e.layer) * a.height + e.y + y) * a.width + e.x + x];
                ASSERT_EQ(o, -1) << textures[i].name << " overlaps texture " << o;
                o = static_cast<int>(i);
            }
    }
}

// Mipmapped textures: every level is the box-filter halving of the one before (halveTexture), at
// the texels shared/texture_levels.glsl names, and no texture's levels overlap another's texels.
TEST(TextureAtlas, MipmapLevelsLieWhereTheShaderReadsThem) {
    std::vector<Texture> textures;
    const uint32_t sizes[][2] = {{64, 64}, {16, 48}, {33, 7}, {64, 1}, {1, 1}, {5, 3}, {1, 9}, {64, 30}};
    std::vector<bool> mipmapped;
    for (uint32_t i = 0; i < 8; ++i) {
        textures.push_back(makeTexture("t" + std::to_string(i), sizes[i][0], sizes[i][1], i, i % 2 == 0));
        mipmapped.push_back(i != 7);  // the last one without levels
    }
    const TextureAtlas a = buildTextureAtlas(textures, {}, mipmapped);
    std::vector<int> owner(size_t(a.width) * a.height * a.layers, -1);
    for (size_t i = 0; i < textures.size(); ++i) {
        const TextureAtlasEntry& e = a.entries[i];
        ASSERT_EQ(e.width, textures[i].width);
        ASSERT_EQ(e.height, textures[i].height);
        const uint32_t expectedLevels = mipmapped[i] ? gpu::mipLevelCount(e.width, e.height) : 1u;
        ASSERT_EQ(e.levels, expectedLevels) << textures[i].name;
        ASSERT_LE(e.x + gpu::mipRectWidth(e.width, e.levels), a.width);
        ASSERT_LE(e.y + gpu::mipRectHeight(e.height, e.levels), a.height);
        Texture level = textures[i];
        for (uint32_t l = 0; l < e.levels; ++l) {
            if (l > 0) level = halveTexture(level);
            ASSERT_EQ(level.width, gpu::mipLevelSize(e.width, l));
            ASSERT_EQ(level.height, gpu::mipLevelSize(e.height, l));
            const uint32_t x0 = gpu::mipLevelColumn(e.width, l), y0 = gpu::mipLevelRow(e.height, l);
            for (uint32_t y = 0; y < level.height; ++y)
                for (uint32_t x = 0; x < level.width; ++x) {
                    ASSERT_EQ(atlasTexel(a, i, x0 + x, y0 + y), level.rgba8[size_t(y) * level.width + x])
                        << textures[i].name << " level " << l;
                    int& o = owner[(size_t(e.layer) * a.height + e.y + y0 + y) * a.width + e.x + x0 + x];
                    ASSERT_EQ(o, -1) << textures[i].name << " level " << l << " overlaps texture " << o;
                    o = static_cast<int>(i);
                }
        }
        if (e.levels > 1) {
            EXPECT_EQ(level.width * level.height, 1u) << textures[i].name << ": the chain ends at 1x1";
        }
    }
}

// mipLevelRow's closed form against the plain sum of the heights above the level.
TEST(TextureAtlas, MipLevelRowIsTheSumOfTheHeightsAbove) {
    for (uint32_t h = 1; h <= 4100; h += (h < 300 ? 1 : 37))
        for (uint32_t level = 0; level <= gpu::mipLevelCount(1, h) + 2; ++level) {
            uint32_t sum = 0;
            for (uint32_t k = 1; k < level; ++k) sum += gpu::mipLevelSize(h, k);
            ASSERT_EQ(gpu::mipLevelRow(h, level), sum) << "h " << h << " level " << level;
        }
    EXPECT_EQ(gpu::mipLevelCount(1, 1), 1u);
    EXPECT_EQ(gpu::mipLevelCount(2, 1), 2u);
    EXPECT_EQ(gpu::mipLevelCount(5, 3), 4u);   // 5x3, 3x2, 2x1, 1x1
    EXPECT_EQ(gpu::mipLevelCount(1024, 1), 11u);
}

// Mipmaps cost texels: a budget that holds the textures alone but not with their levels makes
// the atlas halve them (with a warning), not refuse.
TEST(TextureAtlas, MipmapsCountInTheDeviceBudget) {
    std::vector<Texture> textures{makeTexture("big", 256, 256, 1)};
    TextureLimits limits;
    limits.maxBytes = 256 * 256 * 4;
    const TextureAtlas plain = buildTextureAtlas(textures, limits);
    EXPECT_TRUE(plain.downscaled.empty());
    const TextureAtlas mipmapped = buildTextureAtlas(textures, limits, {true});
    ASSERT_EQ(mipmapped.downscaled.size(), 1u);
    EXPECT_EQ(mipmapped.entries[0].width, 128u);
    EXPECT_EQ(mipmapped.entries[0].levels, 8u);
    EXPECT_LE(mipmapped.bytes(), limits.maxBytes);
}

TEST(TextureAtlas, HalvingAveragesTwoByTwoBlocksInLinearLight) {
    // 4x2 linear: blocks {0, 0, 255, 255} (x 0..1) average to 128 (127.5 rounded), {10 x 4} stays 10.
    Texture t;
    t.name = "t";
    t.width = 4;
    t.height = 2;
    t.rgba8 = {0x000000ffu, 0xff0000ffu, 10, 10, 0x00ff00ffu, 0xffffffffu, 10, 10};
    const Texture h = halveTexture(t);
    ASSERT_EQ(h.width, 2u);
    ASSERT_EQ(h.height, 1u);
    EXPECT_EQ(h.rgba8[0] & 0xffu, 255u);            // R: 255 everywhere
    EXPECT_EQ((h.rgba8[0] >> 8) & 0xffu, 64u);      // G: one 255 of four: 63.75
    EXPECT_EQ((h.rgba8[0] >> 24) & 0xffu, 128u);    // A: two 255 of four
    EXPECT_EQ(h.rgba8[1], 10u);
    // sRGB: black and white average to linear 0.5, which is sRGB 188 (0.7354); alpha stays linear.
    Texture s;
    s.name = "s";
    s.srgb = true;
    s.width = 2;
    s.height = 1;
    s.rgba8 = {0xff000000u, 0xffffffffu};
    const Texture hs = halveTexture(s);
    ASSERT_EQ(hs.width, 1u);
    EXPECT_EQ(hs.rgba8[0] & 0xffu, 188u);
    EXPECT_EQ(hs.rgba8[0] >> 24, 255u);
}

TEST(TextureAtlas, MaxTextureSizeHalvesUntilTheTextureFits) {
    // 8x8 black with the 2x2 block at (2, 4) white: at most 4 texels wide it is 4x4 with texel (1, 2) white.
    Texture t;
    t.name = "marked";
    t.width = 8;
    t.height = 8;
    t.rgba8.assign(64, 0xff000000u);
    for (uint32_t y = 4; y < 6; ++y)
        for (uint32_t x = 2; x < 4; ++x) t.rgba8[y * 8 + x] = 0xffffffffu;
    std::vector<Texture> textures{t, makeTexture("small", 3, 3, 7)};
    const std::vector<std::string> lines = limitTextureSize(textures, 4);
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_EQ(lines[0], "marked: 8x8 -> 4x4");
    ASSERT_EQ(textures[0].width, 4u);
    for (uint32_t y = 0; y < 4; ++y)
        for (uint32_t x = 0; x < 4; ++x)
            EXPECT_EQ(textures[0].rgba8[y * 4 + x], (x == 1 && y == 2) ? 0xffffffffu : 0xff000000u) << x << ", " << y;
    EXPECT_EQ(textures[1].width, 3u) << "textures within the limit stay as they are";
    // The atlas applies the same limit.
    TextureLimits limits;
    limits.maxTextureSize = 2;
    const TextureAtlas a = buildTextureAtlas({t}, limits);
    EXPECT_EQ(a.entries[0].width, 2u);
    ASSERT_EQ(a.downscaled.size(), 1u);
}

TEST(TextureAtlas, TexturesBeyondTheDeviceBudgetAreDownscaledNotRefused) {
    std::vector<Texture> textures;
    for (uint32_t i = 0; i < 6; ++i) textures.push_back(makeTexture("big" + std::to_string(i), 256, 256, i));
    textures.push_back(makeTexture("small", 16, 16, 99));
    TextureLimits limits;
    limits.maxBytes = 4 * 256 * 256 * 2;  // room for two of the six big textures' texels
    const TextureAtlas a = buildTextureAtlas(textures, limits);
    EXPECT_LE(a.bytes(), limits.maxBytes);
    EXPECT_FALSE(a.downscaled.empty());
    EXPECT_EQ(a.entries[6].width, 16u) << "the largest textures shrink first";
    for (const TextureAtlasEntry& e : a.entries) EXPECT_GE(e.width, 16u);
    // Layer limits too: one layer of at most 128x128.
    limits = {};
    limits.maxLayers = 1;
    limits.maxLayerSize = 128;
    const TextureAtlas b = buildTextureAtlas(textures, limits);
    EXPECT_EQ(b.layers, 1u);
    EXPECT_LE(b.width, 128u);
    EXPECT_LE(b.height, 128u);
    // Nothing fits in zero bytes: a device limit, not a bad scene.
    limits = {};
    limits.maxBytes = 0;
    EXPECT_THROW(buildTextureAtlas(textures, limits), std::exception);
}

TEST(TextureAtlas, NoTexturesIsOneBlackTexel) {
    const TextureAtlas a = buildTextureAtlas({}, {});
    EXPECT_EQ(a.texels.size(), 1u);
    EXPECT_EQ(a.bytes(), 4u);
}

}  // namespace
}  // namespace vkp
