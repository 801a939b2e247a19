// The render command's options belong to what reads them: an option of an integrator that was not
// chosen, of --light-sampler photon without it, of --direct raster without it or of --frames
// without it is refused before anything loads (exit 2, naming the option and its owner). These
// runs stop at the command line: no scene is loaded, nothing is rendered.
#include <string>

#include <gtest/gtest.h>

#include "support/cli_runner.h"

namespace vkp {
namespace {

using test::RunResult;
using test::runVkphoton;

const std::string kBox = std::string(VKPHOTON_SCENES) + "/cornell-box.gltf";

void expectRefused(const std::string& args, const std::string& option, const std::string& owner) {
    const RunResult r = runVkphoton("render " + kBox + " " + args + " -o /nonexistent/dir/x.exr");
    EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.output;
    EXPECT_NE(r.output.find(option), std::string::npos) << args << "\n" << r.output;
    EXPECT_NE(r.output.find(owner), std::string::npos) << args << "\n" << r.output;
}

TEST(IntegratorOptions, PathRefusesPhotonOptions) {
    expectRefused("--integrator path --photons 1000", "--photons", "--integrator photon or sppm");
    expectRefused("--photons 1000", "--photons", "--integrator photon or sppm");  // path is the default
    expectRefused("--integrator guided --gather-rays 2", "--gather-rays", "--integrator photon");
    expectRefused("--integrator path --guide-photons 10", "--guide-photons", "--integrator guided");
}

TEST(IntegratorOptions, EachPhotonMethodRefusesTheOthersOptions) {
    expectRefused("--integrator sppm --gather-rays 2", "--gather-rays", "--integrator photon");
    expectRefused("--integrator photon --progressive --caustic-photons 10", "--caustic-photons", "--integrator photon");
    expectRefused("--integrator photon --alpha 0.5", "--alpha", "--integrator sppm");
}

TEST(IntegratorOptions, ProgressiveIsSppmAndGoesOnlyWithPhoton) {
    expectRefused("--integrator guided --progressive", "--progressive", "--integrator sppm");
    expectRefused("--integrator path --progressive", "--progressive", "--integrator sppm");
}

TEST(IntegratorOptions, LightCellsDirectRasterAndFramesOptionsNeedTheirSwitch) {
    expectRefused("--light-photons 1000", "--light-photons", "--light-sampler photon");
    expectRefused("--light-sampler bvh --light-cell-k 4", "--light-cell-k", "--light-sampler photon");
    expectRefused("--area-light-samples 4", "--area-light-samples", "--direct raster");
    expectRefused("--photon-update full", "--photon-update", "--frames");
    expectRefused("--fps 30", "--fps", "--frames");
}

TEST(IntegratorOptions, HelpGroupsOptionsByTheirReaders) {
    const RunResult r = runVkphoton("render --help");
    EXPECT_EQ(r.exitCode, 0);
    for (const char* group : {"photon maps (--integrator photon or sppm)", "final gathering (--integrator photon)",
                              "progressive photon mapping (--integrator sppm)", "guided path tracer (--integrator guided)"})
        EXPECT_NE(r.output.find(group), std::string::npos) << group << "\n" << r.output;
    EXPECT_NE(r.output.find("sppm (stochastic progressive photon mapping"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace vkp
