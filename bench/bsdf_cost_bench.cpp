// Cost of one path vertex's BSDF work (sampleBsdf for the continuation, evalBsdf and pdfBsdf for
// the light sample) in the shared BSDF compiled as C++, for comparing two versions of
// shaders/shared/bsdf.glsl: build this file once against each tree's shaders/ (docs/benchmarks.md,
// "BSDF cost per sample"), e.g.
//   g++ -O3 -std=c++20 -DNDEBUG -I OLD/shaders -o /tmp/bsdf_old bench/bsdf_cost_bench.cpp
//   g++ -O3 -std=c++20 -DNDEBUG -I NEW/shaders -o /tmp/bsdf_new bench/bsdf_cost_bench.cpp
// -DVKP_BSDF_BEFORE_EXTENSIONS for a bsdf.glsl without makeBsdfParams (commit 8b7f00c). Not a
// CMake target: it compiles against another checkout's header. Prints ns per vertex for the
// Cornell box's material (glTF default: rough white dielectric) and a rough metal.
#include <chrono>
#include <cstdio>
#include <random>
#include <vector>

#include "shared/bsdf.glsl"

namespace {

using namespace vkp::gpu;

BsdfParams params(glm::vec3 baseColor, float metallic, float roughness) {
#ifdef VKP_BSDF_BEFORE_EXTENSIONS
    BsdfParams p;
    p.baseColor = baseColor;
    p.metallic = metallic;
    p.roughness = roughness;
    p.transmission = 0.0f;
    p.ior = 1.5f;
    p.thinWalled = 0u;
    return p;
#else
    return makeBsdfParams(baseColor, metallic, roughness);
#endif
}

struct Input {
    glm::vec3 wo, wiLight, u;
};

double nsPerVertex(const BsdfParams& p, const std::vector<Input>& inputs, int repeats, float& sink) {
    double best = 1e30;
    for (int r = 0; r < repeats; ++r) {
        const auto start = std::chrono::steady_clock::now();
        float acc = 0.0f;
        for (const Input& in : inputs) {
            const BsdfSample s = sampleBsdf(p, in.wo, true, true, in.u);
            const glm::vec3 f = evalBsdf(p, in.wo, in.wiLight);
            const float pdf = pdfBsdf(p, in.wo, in.wiLight);
            acc += s.weight.x + s.pdf + f.y + pdf;
        }
        const double ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count();
        best = std::min(best, ns / double(inputs.size()));
        sink += acc;
    }
    return best;
}

}  // namespace

int main() {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> uni(0.0f, 1.0f);
    const auto hemisphere = [&] {
        const float z = std::max(uni(rng), 0.02f), phi = 6.2831853f * uni(rng), r = std::sqrt(1.0f - z * z);
        return glm::vec3(r * std::cos(phi), r * std::sin(phi), z);
    };
    std::vector<Input> inputs(1 << 20);
    for (Input& in : inputs) in = {hemisphere(), hemisphere(), glm::vec3(uni(rng), uni(rng), uni(rng))};
    float sink = 0.0f;
    const double dielectric = nsPerVertex(params(glm::vec3(0.73f), 0.0f, 1.0f), inputs, 5, sink);
    const double metal = nsPerVertex(params(glm::vec3(0.9f, 0.7f, 0.35f), 1.0f, 0.4f), inputs, 5, sink);
    std::printf("rough white dielectric: %.1f ns/vertex, rough metal: %.1f ns/vertex (checksum %g)\n", dielectric,
                metal, double(sink));
    return 0;
}
