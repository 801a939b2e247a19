#include "util/host_memory.h"

#include <fstream>
#include <sstream>
#include <string>

namespace vkp {

uint64_t hostMemoryAvailable() {
    std::ifstream in("/proc/meminfo");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("MemAvailable:", 0) == 0) {
            std::istringstream fields(line.substr(13));
            uint64_t kib = 0;
            fields >> kib;
            return kib * 1024;
        }
    return 0;
}

}  // namespace vkp
