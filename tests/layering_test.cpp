// The include map of host/ (docs/architecture.md, "The parts"): every file has a layer, and a file
// includes only files of its own layer or below; no two files include each other, directly or
// through others. Read from the sources themselves, so a new include that runs upward fails here.
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace vkp {
namespace {

namespace fs = std::filesystem;

const fs::path kHost = fs::path(VKPHOTON_SOURCE_DIR) / "host";

// Layers from the bottom. A file's layer is its folder's, unless a file prefix says otherwise:
// the light BVH and the light-sampling settings sit below the scene's GPU arrays that hold them,
// and the driver (Renderer, its raster direct light) above the light cells it prepares. The view
// command (host/view) is a command like render: it shares app's layer and its render options.
int layerOf(const std::string& file) {
    static const std::vector<std::pair<std::string, int>> kFiles = {
        {"lights/light_tree.", 35}, {"lights/light_sampling.", 35},
        {"render/renderer.", 85}, {"render/raster_direct.", 85}};
    static const std::map<std::string, int> kFolders = {
        {"util", 0}, {"vk", 10}, {"image", 10}, {"scene", 20}, {"bvh", 30}, {"gpu_scene", 40},
        {"passes", 50}, {"render", 60}, {"photon", 70}, {"lights", 80}, {"guiding", 90},
        {"animation", 100}, {"view", 120}, {"app", 120}};
    for (const auto& [prefix, layer] : kFiles)
        if (file.rfind(prefix, 0) == 0) return layer;
    const std::string folder = file.substr(0, file.find('/'));
    const auto it = kFolders.find(folder);
    return it == kFolders.end() ? -1 : it->second;
}

// host-relative path -> the host-relative files it includes.
std::map<std::string, std::vector<std::string>> hostIncludes() {
    std::map<std::string, std::vector<std::string>> includes;
    const std::regex include(R"(^\s*#include\s+"([^"]+)\")");
    for (const auto& entry : fs::recursive_directory_iterator(kHost)) {
        const std::string ext = entry.path().extension().string();
        if (ext != ".h" && ext != ".cpp") continue;
        const std::string file = fs::relative(entry.path(), kHost).generic_string();
        std::vector<std::string>& list = includes[file];
        std::ifstream in(entry.path());
        std::string line;
        std::smatch m;
        while (std::getline(in, line))
            if (std::regex_search(line, m, include) && fs::exists(kHost / m[1].str())) list.push_back(m[1]);
    }
    return includes;
}

TEST(Layering, EveryHostFileHasALayer) {
    for (const auto& [file, list] : hostIncludes()) EXPECT_GE(layerOf(file), 0) << file << ": a folder the map lacks";
}

TEST(Layering, NoIncludeRunsUpward) {
    const auto includes = hostIncludes();
    ASSERT_GT(includes.size(), 100u);
    for (const auto& [file, list] : includes)
        for (const std::string& target : list)
            EXPECT_LE(layerOf(target), layerOf(file)) << file << " includes " << target << ", a layer above it";
}

TEST(Layering, NoFilesIncludeEachOther) {
    const auto includes = hostIncludes();
    // Depth-first search over headers' includes; a back edge is a cycle.
    std::map<std::string, int> state;  // 0 new, 1 on the stack, 2 done
    std::vector<std::string> stack;
    std::function<void(const std::string&)> visit = [&](const std::string& file) {
        state[file] = 1;
        stack.push_back(file);
        const auto it = includes.find(file);
        if (it != includes.end())
            for (const std::string& target : it->second) {
                if (state[target] == 1) {
                    std::string cycle;
                    for (const std::string& f : stack) cycle += f + " -> ";
                    ADD_FAILURE() << "include cycle: " << cycle << target;
                } else if (state[target] == 0) {
                    visit(target);
                }
            }
        stack.pop_back();
        state[file] = 2;
    };
    for (const auto& [file, list] : includes)
        if (state[file] == 0) visit(file);
}

// The check can fail: an include from the seam into a subsystem is caught.
TEST(Layering, AnUpwardIncludeWouldBeCaught) {
    EXPECT_GT(layerOf("photon/photon_map.h"), layerOf("render/frame.h"));
    EXPECT_GT(layerOf("app/cli.h"), layerOf("render/renderer.h"));
    EXPECT_LT(layerOf("lights/light_tree.h"), layerOf("gpu_scene/scene_buffers.h"));
    EXPECT_GT(layerOf("render/renderer.h"), layerOf("lights/light_cells.h"));
}

}  // namespace
}  // namespace vkp
