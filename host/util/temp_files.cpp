#include "util/temp_files.h"

#include <array>
#include <atomic>
#include <cstring>

#include <unistd.h>

namespace vkp {
namespace {

constexpr int kSlots = 16;
constexpr size_t kMaxPath = 4096;

// State per slot: 0 free, 1 being filled or emptied, 2 holds a path.
std::array<std::atomic<int>, kSlots> g_state{};
char g_paths[kSlots][kMaxPath];

}  // namespace

TempFileGuard::TempFileGuard(const std::filesystem::path& path) {
    const std::string& text = path.native();
    if (text.size() >= kMaxPath) return;
    for (int i = 0; i < kSlots; ++i) {
        int expected = 0;
        if (!g_state[i].compare_exchange_strong(expected, 1)) continue;
        std::memcpy(g_paths[i], text.c_str(), text.size() + 1);
        g_state[i].store(2);
        m_slot = i;
        return;
    }
}

TempFileGuard::~TempFileGuard() {
    if (m_slot >= 0) g_state[m_slot].store(0);
}

void removeTempFilesNow() {
    for (int i = 0; i < kSlots; ++i)
        if (g_state[i].load() == 2) ::unlink(g_paths[i]);
}

}  // namespace vkp
