#include "app/info_command.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "lights/default_lighting.h"
#include "lights/backdrop.h"
#include "scene/environment.h"
#include "scene/gltf_extensions.h"
#include "scene/gltf_loader.h"

namespace vkp {
namespace {

using nlohmann::json;

json vec3Json(glm::vec3 v) { return json::array({v.x, v.y, v.z}); }

bool isEmissive(const Material& m) { return glm::any(glm::greaterThan(m.emissive, glm::vec3(0.0f))); }

// Every extension the file names (extensionsUsed, extensionsRequired, or only on a material),
// in the file's order, with what vkphoton does with it.
json extensionsJson(const Scene& scene) {
    std::vector<std::string> names = scene.file.extensionsUsed;
    const auto add = [&](const std::string& name) {
        if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    };
    for (const std::string& name : scene.file.extensionsRequired) add(name);
    for (const Material& m : scene.materials)
        for (const std::string& name : m.extensions) add(name);
    json out = json::array();
    for (const std::string& name : names) {
        const GltfExtension* known = findGltfExtension(name);
        const auto& required = scene.file.extensionsRequired;
        out.push_back({{"name", name},
                       {"required", std::find(required.begin(), required.end(), name) != required.end()},
                       {"support", known ? extensionSupportName(known->support) : "ignored"},
                       {"note", known ? std::string(known->note) : "not known to vkphoton"}});
    }
    return out;
}

std::string byteCount(uint64_t bytes) {
    if (bytes < 1024) return fmt::format("{} bytes", bytes);
    if (bytes < 1024 * 1024) return fmt::format("{:.1f} KiB", double(bytes) / 1024.0);
    return fmt::format("{:.1f} MiB", double(bytes) / (1024.0 * 1024.0));
}

void printText(const json& r) {
    fmt::print("scene        {}\n", r["scene"].get<std::string>());
    fmt::print("triangles    {}{}\n", r["triangles"].get<uint64_t>(),
               r["droppedDegenerateTriangles"].get<uint64_t>()
                   ? fmt::format(" ({} degenerate dropped)", r["droppedDegenerateTriangles"].get<uint64_t>())
                   : "");
    const json& materials = r["materials"];
    fmt::print("materials    {}\n", materials.size());
    constexpr size_t kListed = 20;
    for (size_t i = 0; i < materials.size() && i < kListed; ++i) {
        const json& m = materials[i];
        std::string extensions;
        for (const json& e : m["extensions"]) extensions += (extensions.empty() ? "" : ", ") + e.get<std::string>();
        fmt::print("  {:3} {}{}{}\n", i, m["name"].get<std::string>(), m["emissive"].get<bool>() ? " (emissive)" : "",
                   extensions.empty() ? "" : "  [" + extensions + "]");
    }
    if (materials.size() > kListed) fmt::print("  ... and {} more\n", materials.size() - kListed);
    const json& l = r["lights"];
    fmt::print("lights       {} point, {} spot, {} directional; {} emissive triangles\n", l["point"].get<int>(),
               l["spot"].get<int>(), l["directional"].get<int>(), l["emissiveTriangles"].get<uint64_t>());
    if (l["emissiveTriangles"].get<uint64_t>() > 0)
        fmt::print("             emitters put {:.3g} % of the light a white sky would on the scene ({:.0f} % of "
                   "theirs lands on a surface){}\n",
                   100.0 * l["emitterShare"].get<double>(), 100.0 * l["emitterLanding"].get<double>(),
                   l["defaultSky"].get<bool>()
                       ? fmt::format(": under {:g} %, render adds the white sky", 100.0 * kMinEmitterShare)
                       : std::string());
    for (int node : l["skyBoxNodes"].get<std::vector<int>>())
        fmt::print("             nodes[{}] is a sky box: camera rays see it, the sky lights the scene through it\n", node);
    const json& cameras = r["cameras"];
    fmt::print("cameras      {}{}\n", cameras.size(),
               cameras.empty() ? " (renders use a three-quarter view framing the bounds)" : "");
    for (size_t i = 0; i < cameras.size(); ++i)
        if (cameras[i].contains("orthographicHalfHeight"))
            fmt::print("  {:3} {} (orthographic, {:g} units high)\n", i, cameras[i]["name"].get<std::string>(),
                       2.0 * cameras[i]["orthographicHalfHeight"].get<double>());
        else
            fmt::print("  {:3} {} (vertical field of view {:.1f} degrees)\n", i, cameras[i]["name"].get<std::string>(),
                       cameras[i]["yfovDegrees"].get<double>());
    const json& a = r["animations"];
    fmt::print("animations   {} ({} channels){}\n", a["count"].get<uint64_t>(), a["channels"].get<uint64_t>(),
               a["count"].get<uint64_t>() ? ": played by render --frames; a still render shows the static node poses" : "");
    fmt::print("nodes        {} ({} skins)\n", r["nodes"].get<uint64_t>(), r["skins"].get<uint64_t>());
    if (!r["materialVariants"].empty()) {
        std::string names;
        for (const json& v : r["materialVariants"]) names += (names.empty() ? "" : ", ") + v.get<std::string>();
        fmt::print("variants     {}: {} (render --variant NAME)\n", r["materialVariants"].size(), names);
    }
    const json& extensions = r["extensions"];
    fmt::print("extensions   {}\n", extensions.size());
    for (const json& e : extensions)
        fmt::print("  {:<36} {:<8} {:<9}{}\n", e["name"].get<std::string>(), e["support"].get<std::string>(),
                   e["required"].get<bool>() ? "required" : "", e["note"].get<std::string>());
    const json& t = r["textures"];
    fmt::print("textures     {}, {} decoded (RGBA8)\n", t["count"].get<uint64_t>(),
               byteCount(t["decodedBytes"].get<uint64_t>()));
    const json& b = r["bounds"];
    fmt::print("bounds       ({:.4g}, {:.4g}, {:.4g}) to ({:.4g}, {:.4g}, {:.4g}), size {:.4g} x {:.4g} x {:.4g}\n",
               b["min"][0].get<double>(), b["min"][1].get<double>(), b["min"][2].get<double>(), b["max"][0].get<double>(),
               b["max"][1].get<double>(), b["max"][2].get<double>(), b["size"][0].get<double>(),
               b["size"][1].get<double>(), b["size"][2].get<double>());
}

}  // namespace

json sceneReport(const Scene& scene) {
    json report;
    report["scene"] = scene.source.string();
    // Drawn triangles (every instance counted), and the instancing (docs/bvh.md).
    size_t drawn = scene.triangles.size();
    for (const Instance& instance : scene.instances) drawn += scene.meshes[instance.mesh].triangles.size();
    report["triangles"] = drawn;
    report["instances"] = scene.instances.size();
    report["instancedMeshes"] = scene.meshes.size();
    report["droppedDegenerateTriangles"] = scene.droppedDegenerateTriangles;
    report["materials"] = json::array();
    for (const Material& m : scene.materials)
        report["materials"].push_back({{"name", m.name}, {"emissive", isEmissive(m)}, {"extensions", m.extensions}});
    int byType[3] = {0, 0, 0};
    for (const PunctualLight& light : scene.lights) ++byType[static_cast<int>(light.type)];
    const uint64_t emissiveTriangles = std::count_if(scene.triangles.begin(), scene.triangles.end(),
                                                     [&](const Triangle& t) { return isEmissive(scene.materials[t.material]); });
    report["lights"] = {{"point", byType[int(LightType::Point)]},
                        {"spot", byType[int(LightType::Spot)]},
                        {"directional", byType[int(LightType::Directional)]},
                        {"emissiveTriangles", emissiveTriangles}};
    // The default lighting rule (lights/default_lighting.h): is the white sky added without --env?
    const EmitterShare emitters = emissiveTriangles > 0 ? landedEmitterShare(scene) : EmitterShare{};
    const double share = emitters.share();
    report["lights"]["emitterShare"] = share;
    report["lights"]["emitterPower"] = emitters.emitterPower;  // W, as the light sampler weighs them
    report["lights"]["emitterLanding"] = emitters.landing;     // the fraction of it that lands on the scene
    report["lights"]["defaultSkyPower"] = emitters.skyPower;
    report["lights"]["defaultSky"] = scene.lights.empty() && share < kMinEmitterShare;
    // Sky boxes the default sky would light the scene through (lights/backdrop.h).
    report["lights"]["skyBoxNodes"] = report["lights"]["defaultSky"].get<bool>() ? findBackdrops(scene) : std::vector<int>{};
    report["cameras"] = json::array();
    for (const Camera& c : scene.cameras)
        report["cameras"].push_back(c.orthoHalfHeight > 0.0f
                                        ? json{{"name", c.name}, {"orthographicHalfHeight", double(c.orthoHalfHeight)}}
                                        : json{{"name", c.name}, {"yfovDegrees", glm::degrees(double(c.yfov))}});
    uint64_t channels = 0;
    json animations = json::array();
    for (const AnimationInfo& a : scene.file.animations) {
        channels += a.channels;
        animations.push_back({{"name", a.name}, {"channels", a.channels}, {"samplers", a.samplers}});
    }
    report["animations"] = {{"count", animations.size()}, {"channels", channels}, {"played", false}, {"list", animations}};
    report["nodes"] = scene.file.nodes;
    report["materialVariants"] = scene.file.materialVariants;  // KHR_materials_variants
    report["skins"] = scene.file.skins;
    report["extensions"] = extensionsJson(scene);
    uint64_t texels = 0;
    for (const Texture& t : scene.textures) texels += uint64_t(t.width) * t.height;
    report["textures"] = {{"count", scene.textures.size()}, {"decodedBytes", texels * 4}};
    const Bounds& b = scene.bounds;
    report["bounds"] = b.empty() ? json{{"min", vec3Json(glm::vec3(0))}, {"max", vec3Json(glm::vec3(0))}, {"size", vec3Json(glm::vec3(0))}}
                                 : json{{"min", vec3Json(b.min)}, {"max", vec3Json(b.max)}, {"size", vec3Json(b.extent())}};
    return report;
}

int runInfo(const InfoCommandOptions& options) {
    GltfLimits limits;
    limits.sceneIndex = options.sceneIndex;
    const Scene scene = loadGltf(options.scene, limits);
    const json report = sceneReport(scene);
    if (options.json) fmt::print("{}\n", report.dump(2));
    else printText(report);
    return 0;
}

}  // namespace vkp
