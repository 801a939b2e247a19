// SIGINT (Ctrl-C), SIGTERM and SIGHUP: the first asks the render to stop at its next check
// (render/render_control.h) so what is done so far is written, marked partial, and the process
// exits with 128 + the signal's number (130 for Ctrl-C). A second signal ends the process at
// once with the same code: temporary files are removed (util/temp_files.h), the previous
// outputs stay as they were, nothing new is written. While finished images are renamed into
// place the signals wait (image/atomic_file.h: the EXR and the PNG are replaced together).
#pragma once

#include <atomic>

namespace vkp {

void installInterruptHandler();
const std::atomic<bool>& interruptRequested();
// The first signal received (0: none).
int interruptSignal();
// The process exit code for a run the first signal stopped: 128 + its number.
int interruptExitCode();

}  // namespace vkp
