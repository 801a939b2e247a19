// libFuzzer target over the glTF loader (preflight, schema, tinygltf, accessors, materials,
// images): every input must load or be refused with vkp::InputError / vkp::RuntimeError naming
// the file; anything else (a crash, a sanitizer report, another exception, a hang) is a bug.
// Built with clang, ASan and UBSan by fuzz/CMakeLists.txt; run by the GltfLoaderFuzz test
// (docs/testing.md). The input is written to a file in a folder that also holds the external
// files the seed corpus names (triangle.bin, uv.bin, checker.png), so URIs resolve.
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "scene/gltf_loader.h"
#include "util/errors.h"

namespace {

namespace fs = std::filesystem;

const fs::path& workFolder() {
    static const fs::path folder = [] {
        const char* env = std::getenv("VKPHOTON_FUZZ_FOLDER");
        fs::path dir = env ? fs::path(env) : fs::temp_directory_path() / ("vkphoton-fuzz-" + std::to_string(::getpid()));
        fs::create_directories(dir);
#ifdef VKPHOTON_TEST_DATA
        for (const char* name : {"triangle.bin", "uv.bin", "checker.png"})
            fs::copy_file(fs::path(VKPHOTON_TEST_DATA) / "good" / name, dir / name, fs::copy_options::overwrite_existing);
#endif
        return dir;
    }();
    return folder;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const fs::path path = workFolder() / "input.gltf";
    {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    }
    // Small limits keep each run fast and memory bounded; the checks are the same.
    vkp::GltfLimits limits;
    limits.maxFileBytes = 1u << 20;
    limits.maxImageDimension = 256;
    limits.maxImagePixels = 1u << 16;
    limits.maxTotalImagePixels = 1u << 18;
    limits.maxTriangles = 1u << 16;
    try {
        const vkp::Scene scene = vkp::loadGltf(path, limits);
        if (scene.triangles.empty()) std::abort();  // the loader promises geometry
    } catch (const vkp::InputError& e) {
        if (std::string(e.what()).rfind(path.string() + ": ", 0) != 0) std::abort();  // must name the file
    } catch (const vkp::RuntimeError& e) {
        if (std::string(e.what()).rfind(path.string() + ": ", 0) != 0) std::abort();
    }
    return 0;
}
