// The vkphoton command line (CLI11): one subcommand per file (app/subcommand.h): render, photons,
// guide-grid, info, devices, merge, compare. Render's --integrator choices and option groups come
// from the integrator registry (render/integrator_registry.h). Exit codes: 0 ok, 1 runtime failure,
// 2 bad usage or bad input, 130 interrupted.
#pragma once

namespace vkp {

int runCommandLine(int argc, const char* const* argv);

}  // namespace vkp
