#include "image/atomic_file.h"

#include <atomic>
#include <memory>
#include <cerrno>
#include <stdexcept>
#include <system_error>

#include <csignal>
#include <climits>

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include "util/errors.h"
#include "util/temp_files.h"

namespace vkp {
namespace {

namespace fs = std::filesystem;

std::string errnoText(int error) { return std::error_code(error, std::generic_category()).message(); }

[[noreturn]] void fail(const fs::path& path, const std::string& reason) {
    throw RuntimeError(fmt::format("cannot write {}: {}", path.string(), reason));
}

// Checks the target and returns its folder, creating it if missing.
fs::path prepareFolder(const fs::path& path) {
    if (path.empty()) throw RuntimeError("cannot write a file with an empty path");
    if (!path.has_filename()) fail(path, "the path names a directory, not a file");
    std::error_code ec;
    const fs::file_status target = fs::symlink_status(path, ec);
    // Renaming over a device or a FIFO (say -o /dev/null run as root) would replace the special
    // file itself; a directory would fail later with a less helpful message.
    if (fs::is_directory(fs::status(path, ec))) fail(path, "it is a directory");
    if (fs::exists(target) && !fs::is_regular_file(target) && !fs::is_symlink(target))
        fail(path, "it exists and is not a regular file");

    const fs::path dir = path.has_parent_path() ? path.parent_path() : fs::path(".");
    if (fs::is_directory(fs::status(dir, ec))) return dir;
    // Name the component in the way: "a/file exists and is not a directory" says more than
    // create_directories' "Not a directory".
    for (fs::path p = dir; !p.empty(); p = p.parent_path()) {
        const fs::file_status s = fs::status(p, ec);
        if (fs::exists(s)) {
            if (!fs::is_directory(s)) fail(path, fmt::format("{} exists and is not a directory", p.string()));
            break;
        }
        if (p == p.parent_path()) break;  // the root
    }
    fs::create_directories(dir, ec);
    if (ec) fail(path, fmt::format("cannot create directory {}: {}", dir.string(), ec.message()));
    return dir;
}

fs::path temporaryPath(const fs::path& dir, const fs::path& path) {
    // The counter keeps two threads of one process writing the same target apart; the PID keeps
    // processes apart.
    static std::atomic<unsigned> counter{0};
    std::string name = path.filename().string();
    if (name.size() > 200) name.resize(200);  // stay under NAME_MAX (255) with the suffix
    return dir / fmt::format(".{}.tmp-{}-{}", name, ::getpid(), counter.fetch_add(1));
}

void writeWholeFile(const fs::path& file, std::string_view bytes) {
    // O_TRUNC, not O_EXCL: a run killed earlier with the same PID (common in containers) may
    // have left this very name behind.
    const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0)
        throw std::runtime_error(fmt::format("cannot create a file in {}: {}", file.parent_path().string(), errnoText(errno)));
    size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            const int error = n < 0 ? errno : EIO;
            ::close(fd);
            throw std::runtime_error(errnoText(error));
        }
        done += size_t(n);
    }
    if (::close(fd) != 0) throw std::runtime_error(errnoText(errno));
}

// Flushes the finished file to disk before the rename, so that a crash right after the rename
// cannot leave an empty or partial file under the target name.
void syncToDisk(const fs::path& file) {
    const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) throw std::runtime_error(fmt::format("cannot reopen the finished file: {}", errnoText(errno)));
    const int result = ::fsync(fd);
    const int error = errno;
    ::close(fd);
    // Some file systems cannot sync at all (EINVAL, ENOTSUP); the data is as safe as they allow.
    if (result != 0 && error != EINVAL && error != ENOTSUP && error != ENOSYS)
        throw std::runtime_error(fmt::format("cannot sync to disk: {}", errnoText(error)));
}

// SIGINT, SIGTERM and SIGHUP wait while renames run (app/interrupt.h), so that a set of files is
// replaced together or not at all, whatever the moment of the signal.
class SignalsHeld {
public:
    SignalsHeld() {
        sigset_t set;
        sigemptyset(&set);
        for (const int s : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&set, s);
        pthread_sigmask(SIG_BLOCK, &set, &m_previous);
    }
    ~SignalsHeld() { pthread_sigmask(SIG_SETMASK, &m_previous, nullptr); }

private:
    sigset_t m_previous;
};

void commit(const fs::path& path, const std::function<void(const fs::path&)>& write) {
    const fs::path dir = prepareFolder(path);
    const fs::path temp = temporaryPath(dir, path);
    const TempFileGuard guard(temp);  // a second signal removes it
    std::string reason;
    try {
        write(temp);
        syncToDisk(temp);
        std::error_code ec;
        {
            const SignalsHeld held;
            fs::rename(temp, path, ec);
        }
        if (!ec) return;
        reason = ec.message();
    } catch (const std::exception& e) {
        reason = e.what();
    } catch (...) {
        reason = "unknown error";
    }
    std::error_code ignored;
    fs::remove(temp, ignored);
    fail(path, reason);
}

}  // namespace

void checkWritable(const std::filesystem::path& path) {
    if (path.filename().string().size() > NAME_MAX)
        fail(path, fmt::format("the file name is {} bytes long, more than the {} a name may have",
                               path.filename().string().size(), NAME_MAX));
    const fs::path dir = prepareFolder(path);
    const fs::path probe = temporaryPath(dir, path);
    const TempFileGuard guard(probe);
    const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) fail(path, fmt::format("cannot create a file in {}: {}", dir.string(), errnoText(errno)));
    ::close(fd);
    ::unlink(probe.c_str());
}

void writeFilesTogether(const std::vector<std::pair<std::filesystem::path, std::string>>& files) {
    struct Pending {
        fs::path path, temp, backup;
        std::unique_ptr<TempFileGuard> guard;
        bool replaced = false;
    };
    std::vector<Pending> pending;
    const auto cleanUp = [&] {
        for (Pending& p : pending) {
            std::error_code ignored;
            fs::remove(p.temp, ignored);
            if (!p.backup.empty()) fs::remove(p.backup, ignored);
        }
    };
    std::string reason;
    fs::path failed;
    try {
        for (const auto& [path, bytes] : files) {
            failed = path;
            Pending p;
            p.path = path;
            p.temp = temporaryPath(prepareFolder(path), path);
            p.guard = std::make_unique<TempFileGuard>(p.temp);
            pending.push_back(std::move(p));
            writeWholeFile(pending.back().temp, bytes);
            syncToDisk(pending.back().temp);
        }
    } catch (const std::exception& e) {
        reason = e.what();
    }
    if (reason.empty()) {
        const SignalsHeld held;
        // Keep the previous files (hard links) until every new one is in place, to put them back
        // should a rename fail half-way.
        for (Pending& p : pending) {
            p.backup = p.temp;
            p.backup += ".previous";
            if (::link(p.path.c_str(), p.backup.c_str()) != 0) p.backup.clear();
        }
        for (Pending& p : pending) {
            std::error_code ec;
            fs::rename(p.temp, p.path, ec);
            if (ec) {
                reason = ec.message();
                failed = p.path;
                break;
            }
            p.replaced = true;
        }
        if (!reason.empty())
            for (Pending& p : pending) {
                if (!p.replaced) continue;
                std::error_code ignored;
                if (!p.backup.empty()) fs::rename(p.backup, p.path, ignored);
                else fs::remove(p.path, ignored);
                p.backup.clear();
            }
    }
    cleanUp();
    if (!reason.empty()) fail(failed, reason);
}

void writeBytesAtomically(const std::filesystem::path& path, std::string_view bytes) {
    commit(path, [&](const fs::path& temp) { writeWholeFile(temp, bytes); });
}

void writeTextAtomically(const std::filesystem::path& path, const std::string& text) {
    writeBytesAtomically(path, text);
}

void writeAtomically(const std::filesystem::path& path,
                     const std::function<void(const std::filesystem::path&)>& write) {
    commit(path, write);
}

}  // namespace vkp
