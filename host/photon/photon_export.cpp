#include "photon/photon_export.h"

#include <cstring>
#include <string>

#include <fmt/format.h>

#include "image/atomic_file.h"

namespace vkp {
namespace {

template <typename T> void append(std::string& out, T value) {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));  // the host is little-endian (x86-64, aarch64)
    out.append(bytes, sizeof(T));
}

}  // namespace

PhotonPlyCounts writePhotonPly(const std::filesystem::path& path, std::span<const gpu::GpuPhoton> photons,
                               double nominalPhotonPower) {
    PhotonPlyCounts counts;
    std::string body;
    size_t vertices = 0;
    for (const gpu::GpuPhoton& p : photons) {
        const uint32_t flags = gpu::photonFlags(p);
        if (!(flags & gpu::kPhotonValid)) continue;
        const glm::vec3 power = gpu::photonRelativePower(p) * static_cast<float>(nominalPhotonPower);
        const glm::vec3 dir = gpu::decodeOctahedral(p.direction);
        uint8_t map = 1;
        if (flags & gpu::kPhotonPrimary) { map = 0; ++counts.primary; }
        else if (flags & gpu::kPhotonCaustic) { map = 2; ++counts.caustic; }
        else ++counts.global;
        for (float v : {p.position.x, p.position.y, p.position.z, power.x, power.y, power.z, dir.x, dir.y, dir.z})
            append(body, v);
        append(body, map);
        ++vertices;
    }
    std::string header = fmt::format(
        "ply\nformat binary_little_endian 1.0\ncomment vkphoton photon map (power in watts; map: 0 primary, "
        "1 global, 2 caustic)\nelement vertex {}\nproperty float x\nproperty float y\nproperty float z\n"
        "property float red\nproperty float green\nproperty float blue\nproperty float nx\nproperty float ny\n"
        "property float nz\nproperty uchar map\nend_header\n",
        vertices);
    writeBytesAtomically(path, header + body);
    return counts;
}

}  // namespace vkp
