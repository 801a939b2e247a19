#include "scene/textured_emission.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace vkp {
namespace {

constexpr int kMaxBlocksPerAxis = 8;   // texels of the chosen level per axis at most (per range)
constexpr double kHugeTexels = 1.0e9;  // coordinates beyond this: the whole axis

float srgbToLinear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

struct Range {
    int lo, hi;  // inclusive, within [0, n)
};

// Texels [lo, hi] of an axis of n texels under a wrap mode, as at most two ranges in [0, n).
std::vector<Range> wrapRange(double lo, double hi, int n, TextureWrap mode) {
    if (!(hi - lo < kHugeTexels) || !std::isfinite(lo) || !std::isfinite(hi)) return {{0, n - 1}};
    const long long a = static_cast<long long>(std::floor(lo)), b = static_cast<long long>(std::floor(hi));
    if (mode == TextureWrap::ClampToEdge)
        return {{int(std::clamp<long long>(a, 0, n - 1)), int(std::clamp<long long>(b, 0, n - 1))}};
    if (b - a + 1 >= n) return {{0, n - 1}};
    const auto mod = [&](long long i) { return int(((i % n) + n) % n); };
    if (mode == TextureWrap::Repeat) {
        const int s = mod(a), e = s + int(b - a);
        if (e < n) return {{s, e}};
        return {{s, n - 1}, {0, e - n}};
    }
    // Mirrored repeat: i -> m(i) folds at multiples of n; a range shorter than n crosses at most
    // one fold, whose edge texel (0 or n - 1) joins the endpoints' images.
    const auto mirror = [&](long long i) {
        const long long period = 2ll * n, m = ((i % period) + period) % period;
        return int(m < n ? m : period - 1 - m);
    };
    int s = std::min(mirror(a), mirror(b)), e = std::max(mirror(a), mirror(b));
    const long long fa = a >= 0 ? a / n : (a - n + 1) / n, fb = b >= 0 ? b / n : (b - n + 1) / n;
    if (fa != fb) {
        const int edge = (fb % 2 == 0) ? 0 : n - 1;  // entering an even period starts at 0
        s = std::min(s, edge);
        e = std::max(e, edge);
    }
    return {{s, e}};
}

}  // namespace

TexturedEmission::TexturedEmission(const Scene& scene) : m_scene(scene), m_pyramids(scene.textures.size()) {
    for (const Material& m : scene.materials) {
        if (m.emissiveTexture < 0) continue;
        const int image = scene.textureViews[m.emissiveTexture].image;
        Pyramid& p = m_pyramids[image];
        if (!p.widths.empty()) continue;
        const Texture& t = scene.textures[image];
        uint32_t w = t.width, h = t.height;
        p.widths.push_back(w);
        p.heights.push_back(h);
        int level = 0;
        while (w > 1 || h > 1) {
            const uint32_t cw = (w + 1) / 2, ch = (h + 1) / 2;
            std::vector<glm::vec3> coarse(size_t(cw) * ch);
            for (uint32_t y = 0; y < ch; ++y)
                for (uint32_t x = 0; x < cw; ++x) {
                    glm::vec3 sum(0.0f);
                    int count = 0;
                    for (uint32_t dy = 0; dy < 2; ++dy)
                        for (uint32_t dx = 0; dx < 2; ++dx)
                            if (2 * x + dx < w && 2 * y + dy < h) {
                                sum += texel(image, level, int(2 * x + dx), int(2 * y + dy));
                                ++count;
                            }
                    coarse[size_t(y) * cw + x] = sum / float(count);
                }
            p.levels.push_back(std::move(coarse));
            w = cw;
            h = ch;
            p.widths.push_back(w);
            p.heights.push_back(h);
            ++level;
        }
    }
}

glm::vec3 TexturedEmission::texel(int image, int level, int x, int y) const {
    const Pyramid& p = m_pyramids[image];
    if (level > 0) return p.levels[level - 1][size_t(y) * p.widths[level] + x];
    const Texture& t = m_scene.textures[image];
    const uint32_t v = t.rgba8[size_t(y) * t.width + x];
    glm::vec3 c(float(v & 0xffu) / 255.0f, float((v >> 8) & 0xffu) / 255.0f, float((v >> 16) & 0xffu) / 255.0f);
    if (t.srgb) c = glm::vec3(srgbToLinear(c.x), srgbToLinear(c.y), srgbToLinear(c.z));
    return c;
}

glm::dvec3 TexturedEmission::meanEmission(const Triangle& triangle) const {
    const Material& m = m_scene.materials[triangle.material];
    const glm::dvec3 factor(m.emissive);
    if (m.emissiveTexture < 0 || factor == glm::dvec3(0.0)) return factor;
    const TextureView& view = m_scene.textureViews[m.emissiveTexture];
    const Texture& t = m_scene.textures[view.image];
    glm::dvec2 lo(INFINITY), hi(-INFINITY);
    for (int k = 0; k < 3; ++k) {
        const glm::dvec2 uv(view.texCoord == 1 ? triangle.uv1[k] : triangle.uv[k]);
        const glm::dvec2 st(glm::dot(glm::dvec3(view.uvRow0), glm::dvec3(uv, 1.0)),
                            glm::dot(glm::dvec3(view.uvRow1), glm::dvec3(uv, 1.0)));
        const glm::dvec2 texelCoordinate = st * glm::dvec2(t.width, t.height);
        lo = glm::min(lo, texelCoordinate);
        hi = glm::max(hi, texelCoordinate);
    }
    // Bilinear reads floor(x - 0.5) and the next texel, nearest floor(x): one texel each side covers both.
    const std::vector<Range> xs = wrapRange(lo.x - 1.0, hi.x + 1.0, int(t.width), view.wrapS);
    const std::vector<Range> ys = wrapRange(lo.y - 1.0, hi.y + 1.0, int(t.height), view.wrapT);
    const Pyramid& p = m_pyramids[view.image];
    int widest = 1;
    for (const Range& r : xs) widest = std::max(widest, r.hi - r.lo + 1);
    for (const Range& r : ys) widest = std::max(widest, r.hi - r.lo + 1);
    int level = 0;
    while ((widest >> level) > kMaxBlocksPerAxis && level + 1 < int(p.widths.size())) ++level;
    glm::dvec3 sum(0.0);
    double count = 0.0;
    for (const Range& ry : ys)
        for (const Range& rx : xs)
            for (int y = ry.lo >> level; y <= (ry.hi >> level); ++y)
                for (int x = rx.lo >> level; x <= (rx.hi >> level); ++x) {
                    sum += glm::dvec3(texel(view.image, level, x, y));
                    count += 1.0;
                }
    return factor * (sum / std::max(count, 1.0));
}

}  // namespace vkp
