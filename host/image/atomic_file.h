// Writing a file so that readers never see it half-written: write a temporary file beside the
// target, then rename it over the target. Parent directories are created as needed.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

namespace vkp {

// Calls `write(tempPath)` and renames the result to `path`. On any failure the temporary file
// is removed and RuntimeError names `path` and the reason.
void writeAtomically(const std::filesystem::path& path,
                     const std::function<void(const std::filesystem::path&)>& write);

void writeTextAtomically(const std::filesystem::path& path, const std::string& text);

}  // namespace vkp
