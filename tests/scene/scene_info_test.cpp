// What `vkphoton info` reports: the loader's account of a file (extensions, nodes, animations,
// each material's extensions), the report built from it, and the extension table that
// docs/scene-format.md must repeat.
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <string>

#include <gtest/gtest.h>

#include "app/info_command.h"
#include "scene/gltf_extensions.h"
#include "scene/gltf_loader.h"

namespace vkp {
namespace {

namespace fs = std::filesystem;

// tests/data/info/annotated.gltf: two triangles (materials "glowing coat", emissive with
// KHR_materials_emissive_strength and KHR_materials_clearcoat, and "printed", a 2x1 texture
// with KHR_texture_transform and an unknown extension), a point and a spot light, no camera,
// four nodes (one outside the scene), two animations with 2 and 1 channels.
const fs::path kAnnotated = fs::path(VKPHOTON_TEST_DATA) / "info" / "annotated.gltf";

TEST(SceneFileInfo, TheLoaderReportsWhatItDoesNotRender) {
    const Scene scene = loadGltf(kAnnotated);
    const SceneFileInfo& f = scene.file;
    EXPECT_EQ(f.extensionsUsed, (std::vector<std::string>{"KHR_lights_punctual", "KHR_materials_emissive_strength",
                                                          "KHR_materials_clearcoat", "KHR_texture_transform",
                                                          "EXT_vkphoton_test_unknown"}));
    EXPECT_EQ(f.extensionsRequired, std::vector<std::string>{"KHR_lights_punctual"});
    EXPECT_EQ(f.nodes, 4u);
    EXPECT_EQ(f.skins, 0u);
    ASSERT_EQ(f.animations.size(), 2u);
    EXPECT_EQ(f.animations[0].name, "slide and turn");
    EXPECT_EQ(f.animations[0].channels, 2u);
    EXPECT_EQ(f.animations[0].samplers, 2u);
    EXPECT_EQ(f.animations[1].channels, 1u);
    ASSERT_EQ(scene.materials.size(), 2u);
    EXPECT_EQ(scene.materials[0].extensions,
              (std::vector<std::string>{"KHR_materials_clearcoat", "KHR_materials_emissive_strength"}));
    // Texture references count as the material's too.
    EXPECT_EQ(scene.materials[1].extensions, (std::vector<std::string>{"EXT_vkphoton_test_unknown", "KHR_texture_transform"}));
}

TEST(SceneReport, CountsAndExtensions) {
    const nlohmann::json r = sceneReport(loadGltf(kAnnotated));
    EXPECT_EQ(r["triangles"], 2);
    EXPECT_EQ(r["materials"].size(), 2u);
    EXPECT_EQ(r["materials"][0]["emissive"], true);
    EXPECT_EQ(r["lights"]["point"], 1);
    EXPECT_EQ(r["lights"]["spot"], 1);
    EXPECT_EQ(r["lights"]["directional"], 0);
    EXPECT_EQ(r["lights"]["emissiveTriangles"], 1);
    EXPECT_TRUE(r["cameras"].empty());
    EXPECT_EQ(r["animations"]["count"], 2);
    EXPECT_EQ(r["animations"]["channels"], 3);
    EXPECT_EQ(r["animations"]["played"], false);
    EXPECT_EQ(r["nodes"], 4);
    EXPECT_EQ(r["textures"]["count"], 1);
    EXPECT_EQ(r["textures"]["decodedBytes"], 2 * 1 * 4);
    EXPECT_EQ(r["bounds"]["min"], nlohmann::json::array({0.0, 0.0, -1.0}));
    EXPECT_EQ(r["bounds"]["size"], nlohmann::json::array({1.0, 1.0, 1.0}));
    std::map<std::string, std::pair<std::string, bool>> extensions;  // name -> (support, required)
    for (const auto& e : r["extensions"]) extensions[e["name"]] = {e["support"], e["required"]};
    EXPECT_EQ(extensions.size(), 5u);
    EXPECT_EQ(extensions["KHR_lights_punctual"], std::make_pair(std::string("read"), true));
    EXPECT_EQ(extensions["KHR_materials_emissive_strength"], std::make_pair(std::string("read"), false));
    EXPECT_EQ(extensions["KHR_materials_clearcoat"], std::make_pair(std::string("read"), false));
    EXPECT_EQ(extensions["KHR_texture_transform"], std::make_pair(std::string("read"), false));
    EXPECT_EQ(extensions["EXT_vkphoton_test_unknown"], std::make_pair(std::string("ignored"), false));
}

TEST(GltfExtensions, OnlyReadExtensionsMayBeRequired) {
    EXPECT_TRUE(gltfExtensionIsRead("KHR_materials_volume"));
    EXPECT_TRUE(gltfExtensionIsRead("KHR_texture_transform"));
    EXPECT_TRUE(gltfExtensionIsRead("KHR_materials_anisotropy"));
    EXPECT_FALSE(gltfExtensionIsRead("KHR_materials_diffuse_transmission"));
    EXPECT_FALSE(gltfExtensionIsRead("EXT_never_heard_of_it"));
    EXPECT_EQ(findGltfExtension("EXT_never_heard_of_it"), nullptr);
}

// docs/scene-format.md has a table "| `NAME` | read / ignored | note |": the same rows, in the
// same order, with the same status, as knownGltfExtensions().
TEST(GltfExtensions, TheDocumentationAgreesWithTheTable) {
    std::ifstream in(fs::path(VKPHOTON_SCENES) / ".." / "docs" / "scene-format.md");
    ASSERT_TRUE(in) << "docs/scene-format.md";
    const std::regex row(R"(^\| `([A-Za-z0-9_]+)` \| (read|ignored) \|)");
    std::vector<std::pair<std::string, std::string>> documented;
    for (std::string line; std::getline(in, line);)
        if (std::smatch m; std::regex_search(line, m, row)) documented.emplace_back(m[1], m[2]);
    std::vector<std::pair<std::string, std::string>> table;
    for (const GltfExtension& e : knownGltfExtensions())
        table.emplace_back(std::string(e.name), std::string(extensionSupportName(e.support)));
    EXPECT_EQ(documented, table);
}

}  // namespace
}  // namespace vkp
