#include "render/render_control.h"

#include <limits>

namespace vkp {

double RenderControl::secondsLeft() const {
    if (!deadline) return std::numeric_limits<double>::infinity();
    return std::chrono::duration<double>(*deadline - Clock::now()).count();
}

}  // namespace vkp
