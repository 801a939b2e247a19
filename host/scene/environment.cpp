#include "scene/environment.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>

#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <fmt/format.h>
#include <stb/stb_image.h>

#include "scene/textured_emission.h"
#include "image/exr.h"
#include "scene/environment_distribution.h"
#include "shared/constants.glsl"
#include "shared/sampling.glsl"
#include "scene/scene.h"
#include "util/errors.h"

namespace vkp {
namespace {

std::string lowerExtension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

void checkSize(const std::filesystem::path& path, int64_t width, int64_t height, const EnvironmentLimits& limits) {
    const std::string name = path.string();
    if (width <= 0 || height <= 0)
        throw InputError(fmt::format("--env {}: the map has no pixels ({}x{})", name, width, height));
    if (width < 2 || height < 2)
        throw InputError(fmt::format("--env {}: a {}x{} map is too small to be an equirectangular map (give a constant "
                                     "as --env R,G,B instead)",
                                     name, width, height));
    if (width > limits.maxDimension || height > limits.maxDimension ||
        uint64_t(width) * uint64_t(height) > limits.maxPixels)
        throw InputError(fmt::format("--env {}: {}x{} is larger than the {} pixels a map may have (e.g. 8192x4096); "
                                     "scale it down",
                                     name, width, height, limits.maxPixels));
    const uint64_t bytes = uint64_t(width) * uint64_t(height) * kEnvironmentBytesPerPixel;
    if (bytes > limits.maxMemoryBytes)
        throw InputError(fmt::format("--env {}: {}x{} needs about {:.1f} GiB of memory to load, more than the {:.1f} GiB "
                                     "available",
                                     name, width, height, double(bytes) / double(1ull << 30),
                                     double(limits.maxMemoryBytes) / double(1ull << 30)));
}

Environment readHdr(const std::filesystem::path& path, const EnvironmentLimits& limits) {
    int width = 0, height = 0, components = 0;
    if (!stbi_info(path.c_str(), &width, &height, &components))
        throw InputError(fmt::format("--env {}: not a Radiance .hdr image ({})", path.string(), stbi_failure_reason()));
    if (!stbi_is_hdr(path.c_str()))
        throw InputError(fmt::format("--env {}: not a Radiance .hdr image (no #?RADIANCE header)", path.string()));
    checkSize(path, width, height, limits);
    // stb_image fills a truncated file's missing pixels silently: the smallest valid encoding
    // (run-length scanlines, 2 bytes per run of up to 127 pixels per channel) must fit.
    std::error_code ec;
    const uint64_t bytes = std::filesystem::file_size(path, ec);
    const uint64_t runs = (uint64_t(width) + 126) / 127;
    if (ec || bytes < uint64_t(height) * (4 + 4 * 2 * runs))
        throw InputError(fmt::format("--env {}: cannot decode (the file is truncated: {} bytes for {}x{} pixels)",
                                     path.string(), ec ? 0 : bytes, width, height));
    std::unique_ptr<float, void (*)(void*)> pixels(stbi_loadf(path.c_str(), &width, &height, &components, 3),
                                                   stbi_image_free);
    if (!pixels) throw InputError(fmt::format("--env {}: cannot decode ({})", path.string(), stbi_failure_reason()));
    Environment env;
    env.width = uint32_t(width);
    env.height = uint32_t(height);
    env.rgb.assign(pixels.get(), pixels.get() + size_t(width) * size_t(height) * 3);
    return env;
}

Environment readExrMap(const std::filesystem::path& path, const EnvironmentLimits& limits) {
    try {
        // The header alone first: its size is checked before any pixel is decoded.
        Imf::InputFile file(path.c_str());
        const Imath::Box2i dw = file.header().dataWindow();
        checkSize(path, int64_t(dw.max.x) - dw.min.x + 1, int64_t(dw.max.y) - dw.min.y + 1, limits);
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        throw InputError(fmt::format("--env {}: cannot read EXR: {}", path.string(), e.what()));
    }
    ImageRgb image;
    try {
        image = readExr(path);
    } catch (const std::exception& e) {
        throw InputError(fmt::format("--env {}", e.what()));
    }
    Environment env;
    env.width = image.width;
    env.height = image.height;
    env.rgb = std::move(image.pixels);
    return env;
}

}  // namespace

void EnvironmentSettings::check() const {
    if (!std::isfinite(strength) || strength < 0.0f)
        throw InputError(fmt::format("--env-strength {}: must be a finite number >= 0", strength));
    if (!std::isfinite(rotationDegrees) || std::abs(rotationDegrees) > 1.0e6f)
        throw InputError(fmt::format("--env-rotation {}: must be a finite angle in degrees", rotationDegrees));
}

bool parseEnvironmentConstant(const std::string& text, glm::vec3& radiance) {
    std::vector<float> values;
    size_t start = 0;
    while (start <= text.size()) {
        const size_t end = std::min(text.find(',', start), text.size());
        const std::string part = text.substr(start, end - start);
        size_t used = 0;
        float v = 0.0f;
        try {
            v = std::stof(part, &used);
        } catch (const std::exception&) {
            return false;
        }
        if (used != part.size()) return false;
        values.push_back(v);
        start = end + 1;
    }
    if (values.size() == 1) radiance = glm::vec3(values[0]);
    else if (values.size() == 3) radiance = glm::vec3(values[0], values[1], values[2]);
    else return false;
    return true;
}

Environment loadEnvironmentMap(const std::filesystem::path& path, const EnvironmentLimits& limits) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        throw InputError(fmt::format("--env {}: no such file (give a file, a radiance V or R,G,B)", path.string()));
    const std::string ext = lowerExtension(path);
    Environment env;
    if (ext == ".hdr") env = readHdr(path, limits);
    else if (ext == ".exr") env = readExrMap(path, limits);
    else
        throw InputError(fmt::format("--env {}: unknown map format '{}' (an equirectangular .hdr or .exr)", path.string(),
                                     ext));
    for (size_t i = 0; i < env.rgb.size(); ++i)
        if (!std::isfinite(env.rgb[i]) || env.rgb[i] < 0.0f)
            throw InputError(fmt::format("--env {}: pixel ({}, {}) is {}: a map's radiance must be finite and >= 0",
                                         path.string(), (i / 3) % env.width, (i / 3) / env.width, env.rgb[i]));
    bool black = true;
    for (float v : env.rgb) black = black && v == 0.0f;
    if (black) throw InputError(fmt::format("--env {}: every pixel is black: the map gives no light", path.string()));
    env.present = true;
    env.source = path.string();
    return env;
}

bool sceneHasLights(const Scene& scene) {
    if (!scene.lights.empty()) return true;
    std::vector<bool> emissive(scene.materials.size());
    for (size_t i = 0; i < emissive.size(); ++i)
        emissive[i] = glm::any(glm::greaterThan(scene.materials[i].emissive, glm::vec3(0.0f)));
    for (const Triangle& t : scene.triangles)
        if (t.material < emissive.size() && emissive[t.material]) return true;
    return false;
}

EmitterShare emitterShare(const Scene& scene) {
    EmitterShare share;
    const TexturedEmission emission(scene);
    for (const Triangle& t : scene.triangles) {
        if (t.material >= scene.materials.size()) continue;
        const Material& m = scene.materials[t.material];
        if (!glm::any(glm::greaterThan(m.emissive, glm::vec3(0.0f)))) continue;
        const double le = gpu::luminance(glm::vec3(emission.meanEmission(t)));
        const double area = 0.5 * glm::length(glm::cross(glm::dvec3(t.p[1] - t.p[0]), glm::dvec3(t.p[2] - t.p[0])));
        share.emitterPower += gpu::kPi * le * area * (m.doubleSided ? 2.0 : 1.0);
    }
    Environment sky;
    sky.present = true;
    sky.radiance = glm::vec3(1.0f);
    const double radius = scene.bounds.empty() ? 0.0 : 0.5 * glm::length(glm::dvec3(scene.bounds.extent()));
    share.skyPower = environmentPower(sky, std::max(radius, 1e-6));
    return share;
}

}  // namespace vkp
