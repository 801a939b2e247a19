#include "app/cli.h"

#include <memory>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/cli_options.h"
#include "app/subcommand.h"
#include "util/errors.h"
#include "util/printable.h"

namespace vkp {

int runCommandLine(int argc, const char* const* argv) {
    CLI::App app{"vkphoton: a Vulkan compute photon mapper and path tracer"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "vkphoton 0.1.0");

    std::vector<std::unique_ptr<Subcommand>> commands;
    commands.push_back(addRenderCommand(app));
    commands.push_back(addPhotonsCommand(app));
    commands.push_back(addGuideGridCommand(app));
    commands.push_back(addViewCommand(app));
    commands.push_back(addInfoCommand(app));
    commands.push_back(addDevicesCommand(app));
    commands.push_back(addMergeCommand(app));
    commands.push_back(addCompareCommand(app));

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e) == 0 ? kExitOk : kExitBadInput;
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e) == 0 ? kExitOk : kExitBadInput;
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e) == 0 ? kExitOk : kExitBadInput;
    } catch (const CLI::ParseError& e) {
        // CLI11 quotes the arguments: escape them (a value may hold terminal escapes).
        if (e.get_exit_code() == 0) return kExitOk;
        fmt::print(stderr, "error: {}\nRun with --help for more information.\n", printable(e.what()));
        return kExitBadInput;
    }

    try {
        refuseEmptyValues(app);
        for (const std::unique_ptr<Subcommand>& command : commands)
            if (command->app().parsed()) return command->run();
        return kExitBadInput;  // require_subcommand(1) makes this unreachable
    } catch (const InputError& e) {
        fmt::print(stderr, "error: {}\n", printable(e.what()));
        return kExitBadInput;
    } catch (const std::exception& e) {
        fmt::print(stderr, "error: {}\n", printable(e.what()));
        return kExitRuntimeFailure;
    }
}

}  // namespace vkp
