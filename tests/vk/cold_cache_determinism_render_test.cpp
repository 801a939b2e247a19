// Same seed, same image (docs/architecture.md, "Determinism") however the device got its kernels
// and however it schedules them: a render whose kernels lavapipe compiles afresh (an empty shader
// cache) on one thread, and one that loads them from that cache and runs on four, give the same
// pixels bit for bit. The photon integrator on the glass scene is the case once suspected of a
// cold-cache dependence (it was the image check's byte comparison; see compare_command_test.cpp),
// and it has the parts where scheduling could leak into the image: photon slots, compaction, the
// grid build, the radiance photons and the caustic map.
#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "support/cli_runner.h"
#include "util/errors.h"

namespace vkp {
namespace {

namespace fs = std::filesystem;

using test::RunResult;

bool holdsFiles(const fs::path& dir) {
    if (!fs::exists(dir)) return false;
    for (const auto& entry : fs::recursive_directory_iterator(dir))
        if (entry.is_regular_file()) return true;
    return false;
}

TEST(ColdCacheDeterminism, PhotonIntegratorGivesTheSamePixelsColdOrWarmOnOneThreadOrFour) {
    const fs::path dir = test::freshTempDir("determinism", "cold-warm");
    const fs::path cache = dir / "mesa-cache";
    const std::string render = "render " + std::string(VKPHOTON_SCENES) +
                               "/cornell-glass.gltf --integrator photon --width 32 --height 32 --spp 2 --seed 3 "
                               "--photons 20000 --caustic-photons 20000 --validate --quiet -o ";
    const std::string mesaCache = "MESA_SHADER_CACHE_DIR=" + cache.string() + " MESA_SHADER_CACHE_DISABLE=false ";

    const RunResult cold = test::runVkphoton(render + (dir / "cold.exr").string(), mesaCache + "LP_NUM_THREADS=1");
    ASSERT_EQ(cold.exitCode, 0) << cold.output;
    // On lavapipe the first run filled the cache, so the second loads its kernels instead of
    // compiling them (other drivers ignore these variables: then this compares two runs).
    const char* icd = std::getenv("VK_ICD_FILENAMES");
    if (icd && std::string(icd).find("lvp") != std::string::npos) {
        ASSERT_TRUE(holdsFiles(cache)) << "lavapipe wrote no shader cache: the second run would not be warm";
    }
    const RunResult warm = test::runVkphoton(render + (dir / "warm.exr").string(), mesaCache + "LP_NUM_THREADS=4");
    ASSERT_EQ(warm.exitCode, 0) << warm.output;

    const RunResult same =
        test::runVkphoton("compare " + (dir / "cold.exr").string() + " " + (dir / "warm.exr").string());
    EXPECT_EQ(same.exitCode, kExitOk) << same.output;
}

}  // namespace
}  // namespace vkp
