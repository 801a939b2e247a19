#include "image/atomic_file.h"

#include <fstream>
#include <system_error>

#include <fmt/format.h>
#include <unistd.h>

#include "util/errors.h"

namespace vkp {

void writeAtomically(const std::filesystem::path& path,
                     const std::function<void(const std::filesystem::path&)>& write) {
    namespace fs = std::filesystem;
    const fs::path dir = path.has_parent_path() ? path.parent_path() : fs::path(".");
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) throw RuntimeError(fmt::format("cannot write {}: cannot create {}: {}", path.string(), dir.string(), ec.message()));
    const fs::path temp = dir / fmt::format(".{}.tmp-{}", path.filename().string(), ::getpid());
    try {
        write(temp);
    } catch (const std::exception& e) {
        fs::remove(temp, ec);
        throw RuntimeError(fmt::format("cannot write {}: {}", path.string(), e.what()));
    }
    fs::rename(temp, path, ec);
    if (ec) {
        fs::remove(temp, ec);
        throw RuntimeError(fmt::format("cannot write {}: {}", path.string(), ec.message()));
    }
}

void writeTextAtomically(const std::filesystem::path& path, const std::string& text) {
    writeAtomically(path, [&](const std::filesystem::path& temp) {
        std::ofstream out(temp, std::ios::binary);
        out << text;
        out.flush();
        if (!out) throw std::runtime_error("write failed");
    });
}

}  // namespace vkp
