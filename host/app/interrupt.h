// SIGINT (Ctrl-C) handling: the first signal asks the render to stop after its current batch so
// the samples so far are written (marked partial); a second one exits at once.
#pragma once

#include <atomic>

namespace vkp {

void installInterruptHandler();
const std::atomic<bool>& interruptRequested();

}  // namespace vkp
