#include "app/interrupt.h"

#include <csignal>
#include <unistd.h>

namespace vkp {
namespace {

std::atomic<bool> g_interrupted{false};

extern "C" void onInterrupt(int) {
    if (g_interrupted.exchange(true)) _exit(130);
    constexpr char kMessage[] = "\ninterrupted: finishing the current batch and writing a partial image "
                                "(Ctrl-C again to abort)\n";
    [[maybe_unused]] auto written = write(STDERR_FILENO, kMessage, sizeof(kMessage) - 1);
}

}  // namespace

void installInterruptHandler() {
    struct sigaction action {};
    action.sa_handler = onInterrupt;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, nullptr);
}

const std::atomic<bool>& interruptRequested() { return g_interrupted; }

}  // namespace vkp
