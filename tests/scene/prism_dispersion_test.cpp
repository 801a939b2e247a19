// KHR_materials_dispersion through a glass prism (docs/materials.md, "Dispersion"): an orthographic
// camera looks through a 30-degree prism at an emitter whose edge lies where Snell's law sends the
// 560 nm light. Wavelengths below 560 nm (bent more) reach the emitter and longer ones pass beside
// it, so the pixels show the basis' share of the short wavelengths, per channel: blue far above
// red, as this file computes from Snell's law and the Fresnel equations at every wavelength. With
// dispersion 0 every wavelength reaches it (white), in the same bits as without the extension.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/base64.h"
#include "support/cli_runner.h"
#include "image/exr.h"
#include "shared/dispersion.glsl"

namespace vkp {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr double kApex = 30.0 * M_PI / 180.0;  // between the front face (z = 0) and the back face
constexpr double kIor = 1.5;
// The emitter is small and near: rays leave surfaces 1e-4 of the scene's reach away
// (scene_access.glsl rayEpsilon), which moves where they land by that much; against the
// emitter's distance this shifts the edge by about half a nanometre here (3.5 nm with an emitter
// 300 units wide at 50 units).
constexpr double kEmitterZ = -10.0;
constexpr double kEmitterSize = 3.0;

// The back face: z = -(0.5 + (x + 1) tan A) over x, y in [-1, 1].
double backZ(double x) { return -(0.5 + (x + 1.0) * std::tan(kApex)); }

// Unpolarised Fresnel reflectance from index n1 into n2 at incidence cosine c (exact).
double fresnel(double n1, double n2, double c) {
    const double s2 = (n1 / n2) * (n1 / n2) * (1.0 - c * c);
    if (s2 >= 1.0) return 1.0;
    const double ct = std::sqrt(1.0 - s2);
    const double rs = (n1 * c - n2 * ct) / (n1 * c + n2 * ct), rp = (n1 * ct - n2 * c) / (n1 * ct + n2 * c);
    return 0.5 * (rs * rs + rp * rp);
}

// Where the camera's central ray lands on the emitter's plane for index n: straight through the
// front face, refracted at the back face (incidence A) by Snell's law, sin(t) = n sin(A), leaving
// at t - A from the -z axis towards +x.
double landingX(double n) {
    const double deviation = std::asin(n * std::sin(kApex)) - kApex;
    return (backZ(0.0) - kEmitterZ) * std::tan(deviation);
}

// What the path tracer carries through both faces: T = (1 - F(front)) (1 - F(back)) (the eta^2
// of entering and leaving cancel).
double transmitted(double n) { return (1.0 - fresnel(1.0, n, 1.0)) * (1.0 - fresnel(n, 1.0, std::cos(kApex))); }

json prismScene(double dispersion, double edgeX, bool withExtension) {
    const double zl = backZ(-1.0), zr = backZ(1.0);
    std::vector<float> p = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0,                                 // front
                            -1, -1, float(zl), 1, -1, float(zr), 1, 1, float(zr), -1, 1, float(zl),  // back
                            float(edgeX), -float(kEmitterSize), float(kEmitterZ), float(edgeX + kEmitterSize), -float(kEmitterSize), float(kEmitterZ),
                            float(edgeX + kEmitterSize), float(kEmitterSize), float(kEmitterZ), float(edgeX), float(kEmitterSize), float(kEmitterZ)};
    // Counter-clockwise seen from outside: front, back, x = -1, x = 1, y = -1, y = 1; then the emitter.
    std::vector<uint16_t> prism = {0, 1, 2, 0, 2, 3, 4, 6, 5, 4, 7, 6, 0, 3, 7, 0, 7, 4,
                                   1, 5, 6, 1, 6, 2, 0, 4, 5, 0, 5, 1, 3, 2, 6, 3, 6, 7};
    std::vector<uint16_t> emitter = {8, 9, 10, 8, 10, 11};
    std::vector<uint8_t> bytes(p.size() * 4 + (prism.size() + emitter.size()) * 2);
    std::memcpy(bytes.data(), p.data(), p.size() * 4);
    std::memcpy(bytes.data() + p.size() * 4, prism.data(), prism.size() * 2);
    std::memcpy(bytes.data() + p.size() * 4 + prism.size() * 2, emitter.data(), emitter.size() * 2);
    json glass = {{"pbrMetallicRoughness", {{"metallicFactor", 0.0}, {"roughnessFactor", 0.0}}},
                  {"extensions",
                   {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}},
                    {"KHR_materials_volume", {{"thicknessFactor", 1.0}}},
                    {"KHR_materials_ior", {{"ior", kIor}}}}}};
    const json light = {{"pbrMetallicRoughness", {{"baseColorFactor", {0, 0, 0, 1}}}}, {"emissiveFactor", {1, 1, 1}},
                        {"doubleSided", true}};
    const auto primitive = [](int indices, int material) {
        return json::object({{"attributes", {{"POSITION", 0}}}, {"indices", indices}, {"material", material}});
    };
    const auto view = [](size_t offset, size_t length) {
        return json::object({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", length}});
    };
    json doc;
    doc["asset"] = {{"version", "2.0"}};
    doc["extensionsUsed"] = {"KHR_materials_transmission", "KHR_materials_volume", "KHR_materials_ior"};
    doc["scene"] = 0;
    doc["scenes"] = json::array({json::object({{"nodes", {0, 1, 2}}})});
    doc["nodes"] = json::array({json::object({{"mesh", 0}}), json::object({{"mesh", 1}}),
                                json::object({{"camera", 0}, {"translation", {0, 0, 5}}})});
    doc["cameras"] = json::array({json::object(
        {{"type", "orthographic"}, {"orthographic", {{"xmag", 0.01}, {"ymag", 0.01}, {"znear", 0.01}, {"zfar", 200}}}})});
    doc["meshes"] = json::array({json::object({{"primitives", json::array({primitive(1, 0)})}}),
                                 json::object({{"primitives", json::array({primitive(2, 1)})}})});
    doc["materials"] = json::array({glass, light});
    doc["buffers"] = json::array(
        {json::object({{"byteLength", bytes.size()}, {"uri", "data:application/octet-stream;base64," + test::base64(bytes)}})});
    doc["bufferViews"] = json::array({view(0, p.size() * 4), view(p.size() * 4, prism.size() * 2),
                                      view(p.size() * 4 + prism.size() * 2, emitter.size() * 2)});
    doc["accessors"] = json::array(
        {json::object({{"bufferView", 0}, {"componentType", 5126}, {"count", 12}, {"type", "VEC3"},
                       {"min", {-1, -kEmitterSize, kEmitterZ}}, {"max", {edgeX + kEmitterSize, kEmitterSize, 0}}}),
         json::object({{"bufferView", 1}, {"componentType", 5123}, {"count", prism.size()}, {"type", "SCALAR"}}),
         json::object({{"bufferView", 2}, {"componentType", 5123}, {"count", emitter.size()}, {"type", "SCALAR"}})});
    if (withExtension) {
        doc["materials"][0]["extensions"]["KHR_materials_dispersion"] = {{"dispersion", dispersion}};
        doc["extensionsUsed"].push_back("KHR_materials_dispersion");
    }
    return doc;
}

std::vector<float> render(const fs::path& dir, const std::string& name, const json& doc) {
    std::ofstream(dir / (name + ".gltf")) << doc.dump();
    const fs::path exr = dir / (name + ".exr");
    const test::RunResult r = test::runVkphoton("render " + (dir / (name + ".gltf")).string() +
                                                " --quiet --env 0 --spp 512 --width 8 --height 8 -o " + exr.string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.find("not rendered"), std::string::npos) << r.output;
    return r.exitCode == 0 ? readExr(exr).pixels : std::vector<float>{};
}

glm::dvec3 meanPixel(const std::vector<float>& pixels) {
    glm::dvec3 sum(0.0);
    for (size_t i = 0; i + 2 < pixels.size(); i += 3) sum += glm::dvec3(pixels[i], pixels[i + 1], pixels[i + 2]);
    return sum / double(pixels.size() / 3);
}

TEST(PrismDispersion, ShortWavelengthsBendOntoTheEmitter) {
    const fs::path dir = test::freshTempDir("prism-dispersion", "split");
    constexpr double kDispersion = 1.0;  // Abbe number 20
    const double edge = landingX(gpu::dispersiveIor(float(kIor), float(kDispersion), 560.0f));
    // The expected pixel: the basis over the wavelengths that land on the emitter, times what the
    // two faces let through at each one.
    glm::dvec3 expected(0.0);
    constexpr int kSteps = 4000;
    for (int i = 0; i < kSteps; ++i) {
        const float lambda = gpu::kWavelengthMin + (gpu::kWavelengthMax - gpu::kWavelengthMin) * (i + 0.5f) / kSteps;
        const double n = gpu::dispersiveIor(float(kIor), float(kDispersion), lambda);
        if (landingX(n) > edge)
            expected += glm::dvec3(gpu::spectralBasis(lambda)) * (transmitted(n) * (gpu::kWavelengthMax - gpu::kWavelengthMin) / kSteps);
    }
    ASSERT_GT(expected.z, 3.0 * expected.x);  // the geometry sends blue onto the emitter, red past it
    const glm::dvec3 shown = meanPixel(render(dir, "dispersive", prismScene(kDispersion, edge, true)));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(shown[c], expected[c], 0.01 + 0.03 * expected[c]) << "channel " << c;
    EXPECT_GT(shown.z, 3.0 * shown.x);
    std::printf("prism: shown (%.4f, %.4f, %.4f), Snell's law (%.4f, %.4f, %.4f)\n", shown.x, shown.y, shown.z, expected.x,
                expected.y, expected.z);

    // Dispersion 0 with the edge at 640 nm's landing, which the index at 587.6 nm passes: white,
    // T(1.5) in every channel, and the same bits as the prism without the extension.
    const double edge640 = landingX(gpu::dispersiveIor(float(kIor), float(kDispersion), 640.0f));
    ASSERT_GT(landingX(kIor), edge640 + 0.02);  // beyond the pixels' spread (0.02 across)
    const std::vector<float> none = render(dir, "none", prismScene(0.0, edge640, true));
    const std::vector<float> plain = render(dir, "plain", prismScene(0.0, edge640, false));
    const glm::dvec3 white = meanPixel(none);
    std::printf("prism, dispersion 0: shown (%.4f, %.4f, %.4f), T(1.5) = %.4f\n", white.x, white.y, white.z, transmitted(kIor));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(white[c], transmitted(kIor), 0.02 * transmitted(kIor)) << "channel " << c;
    ASSERT_EQ(none.size(), plain.size());
    EXPECT_EQ(std::memcmp(none.data(), plain.data(), none.size() * sizeof(float)), 0);
}

}  // namespace
}  // namespace vkp
