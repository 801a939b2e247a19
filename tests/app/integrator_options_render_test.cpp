// --integrator sppm is the progressive photon mapping --progressive rendered: the same pixels, bit
// for bit (`vkphoton compare`), and the same integrator named in the stats.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "support/cli_runner.h"

namespace vkp {
namespace {

using test::RunResult;
using test::runVkphoton;

TEST(IntegratorOptionsRender, SppmRendersWhatProgressiveRendered) {
    const std::filesystem::path dir = test::freshTempDir("IntegratorOptions", "Sppm");
    const std::string scene = std::string(VKPHOTON_SCENES) + "/cornell-glass.gltf";
    const std::string common = " --validate --quiet --spp 3 --width 24 --height 24 --photons 4000 --seed 5 ";
    const std::string a = (dir / "sppm.exr").string(), b = (dir / "progressive.exr").string(),
                      c = (dir / "photon-progressive.exr").string(), d = (dir / "photon.exr").string();
    ASSERT_EQ(runVkphoton("render " + scene + common + "--integrator sppm -o " + a).exitCode, 0);
    ASSERT_EQ(runVkphoton("render " + scene + common + "--progressive -o " + b).exitCode, 0);
    ASSERT_EQ(runVkphoton("render " + scene + common + "--integrator photon --progressive -o " + c).exitCode, 0);
    ASSERT_EQ(runVkphoton("render " + scene + common + "--integrator photon --caustic-photons 4000 -o " + d).exitCode, 0);
    EXPECT_EQ(runVkphoton("compare --quiet " + a + " " + b).exitCode, 0);
    EXPECT_EQ(runVkphoton("compare --quiet " + a + " " + c).exitCode, 0);
    EXPECT_EQ(runVkphoton("compare --quiet " + a + " " + d).exitCode, 3);  // the two-pass method differs
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace vkp
