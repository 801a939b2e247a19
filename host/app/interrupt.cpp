#include "app/interrupt.h"

#include <csignal>
#include <unistd.h>

#include "util/temp_files.h"

namespace vkp {
namespace {

std::atomic<bool> g_interrupted{false};
std::atomic<int> g_signal{0};

void say(const char* text, size_t length) { [[maybe_unused]] auto written = write(STDERR_FILENO, text, length); }

extern "C" void onSignal(int signal) {
    int none = 0;
    g_signal.compare_exchange_strong(none, signal);  // before the flag: whoever sees it sees the signal
    if (g_interrupted.exchange(true)) {
        removeTempFilesNow();
        constexpr char kAbort[] = "\nsecond signal: stopped at once; nothing new was written\n";
        say(kAbort, sizeof(kAbort) - 1);
        _exit(128 + g_signal.load());
    }
    constexpr char kMessage[] = "\ninterrupted: stopping at the next check and writing a partial image "
                                "(a second signal stops at once, writing nothing)\n";
    say(kMessage, sizeof(kMessage) - 1);
}

}  // namespace

void installInterruptHandler() {
    struct sigaction action {};
    action.sa_handler = onSignal;
    sigemptyset(&action.sa_mask);
    for (const int signal : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&action.sa_mask, signal);
    for (const int signal : {SIGINT, SIGTERM, SIGHUP}) sigaction(signal, &action, nullptr);
}

const std::atomic<bool>& interruptRequested() { return g_interrupted; }

int interruptSignal() { return g_signal.load(); }

int interruptExitCode() { return 128 + (g_signal.load() ? g_signal.load() : SIGINT); }

}  // namespace vkp
