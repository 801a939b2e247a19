// Running the vkphoton binary from a test: its exit code and what it printed, and a fresh
// temporary folder per test (cli_test.cpp, tiles_test.cpp).
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <string>

namespace vkp::test {

struct RunResult {
    int exitCode = -1;
    std::string output;  // stdout and stderr
};

// `environment`: assignments put before the command ("VK_ICD_FILENAMES=...").
inline RunResult runVkphoton(const std::string& args, const std::string& environment = "") {
    const std::string command = (environment.empty() ? "" : "env " + environment + " ") + std::string(VKPHOTON_BINARY) +
                                " " + args + " 2>&1";
    RunResult result;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return result;
    char buffer[4096];
    size_t n;
    while ((n = fread(buffer, 1, sizeof(buffer), pipe)) > 0) result.output.append(buffer, n);
    const int status = pclose(pipe);
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

// An empty folder vkphoton-<suite>-<name>-<pid> under the system's temporary directory.
inline std::filesystem::path freshTempDir(const std::string& suite, const std::string& name) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("vkphoton-" + suite + "-" + name + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

}  // namespace vkp::test
