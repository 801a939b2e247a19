// Temporary files being written (image/atomic_file.h), registered so that a signal handler can
// remove them before the process exits: no ".NAME.tmp-PID-N" is left behind by any signal that
// can be caught (SIGINT, SIGTERM, SIGHUP; app/interrupt.h).
#pragma once

#include <filesystem>

namespace vkp {

// Registers `path` for removal by removeTempFilesNow() while the guard lives.
class TempFileGuard {
public:
    explicit TempFileGuard(const std::filesystem::path& path);
    ~TempFileGuard();
    TempFileGuard(const TempFileGuard&) = delete;
    TempFileGuard& operator=(const TempFileGuard&) = delete;

private:
    int m_slot = -1;  // -1: the table was full (or the path too long): not registered
};

// Unlinks every registered file. Async-signal-safe: only unlink() on fixed buffers.
void removeTempFilesNow();

}  // namespace vkp
