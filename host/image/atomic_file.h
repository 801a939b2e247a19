// Writing a file so that readers never see it half-written: the content goes to a temporary file
// beside the target (".NAME.tmp-PID-N"), which is flushed to disk and then renamed over the
// target. A failed or interrupted write leaves the previous target, if any, untouched, and no
// temporary file (short of the process being killed mid-write). Missing parent directories are
// created.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace vkp {

// Writes `bytes` to `path` atomically. On any failure the temporary file is removed and
// RuntimeError names `path` and the reason.
void writeBytesAtomically(const std::filesystem::path& path, std::string_view bytes);

void writeTextAtomically(const std::filesystem::path& path, const std::string& text);

// Checks, before any work, that `path` can be written: a file name within NAME_MAX, not a
// directory or special file, a folder that exists or can be created (it is created) and lets
// us create a file. RuntimeError naming `path` and the reason otherwise.
void checkWritable(const std::filesystem::path& path);

// Writes several files (an EXR and its PNG) so that they are replaced together or not at all:
// every temporary file is written and synced first, then all are renamed with SIGINT, SIGTERM
// and SIGHUP held, the previous files kept as hard links until the last rename succeeded.
void writeFilesTogether(const std::vector<std::pair<std::filesystem::path, std::string>>& files);

// For writers that insist on opening the file themselves: calls `write(tempPath)`, which must
// create and fully write and close `tempPath` (or throw), then syncs it and renames it to `path`.
// Failures as above; an exception from `write` becomes the reason.
void writeAtomically(const std::filesystem::path& path,
                     const std::function<void(const std::filesystem::path&)>& write);

}  // namespace vkp
