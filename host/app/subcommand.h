// One vkphoton subcommand on the command line (app/cli.cpp): it registers itself and its options
// on the application, and after parsing runs what they say. Each lives in its own file
// (app/*_cli.cpp) and owns only the options it reads.
#pragma once

#include <memory>

namespace CLI { class App; }

namespace vkp {

class Subcommand {
public:
    virtual ~Subcommand() = default;
    // The CLI11 subcommand, to see whether it was parsed.
    virtual const CLI::App& app() const = 0;
    // Checks the parsed options (InputError: bad usage, exit 2) and runs; returns the exit code.
    virtual int run() = 0;
};

std::unique_ptr<Subcommand> addRenderCommand(CLI::App& app);
std::unique_ptr<Subcommand> addPhotonsCommand(CLI::App& app);
std::unique_ptr<Subcommand> addGuideGridCommand(CLI::App& app);
std::unique_ptr<Subcommand> addViewCommand(CLI::App& app);
// info, devices, merge, compare: the commands that render nothing.
std::unique_ptr<Subcommand> addInfoCommand(CLI::App& app);
std::unique_ptr<Subcommand> addDevicesCommand(CLI::App& app);
std::unique_ptr<Subcommand> addMergeCommand(CLI::App& app);
std::unique_ptr<Subcommand> addCompareCommand(CLI::App& app);

}  // namespace vkp
