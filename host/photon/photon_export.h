// Writing photon maps for inspection: binary little-endian PLY point clouds that point-cloud
// viewers (MeshLab, CloudCompare, Blender) open directly.
#pragma once

#include <filesystem>
#include <span>

#include "shared/photon.glsl"

namespace vkp {

struct PhotonPlyCounts {
    size_t caustic = 0;
    size_t global = 0;
    size_t primary = 0;
};

// One vertex per valid photon: x y z (float, world), power r g b (float, watts), nx ny nz (float,
// the incoming direction, towards where the photon came from), and `map` (uchar: 0 primary,
// 1 global, 2 caustic). Written atomically.
PhotonPlyCounts writePhotonPly(const std::filesystem::path& path, std::span<const gpu::GpuPhoton> photons,
                               double nominalPhotonPower);

}  // namespace vkp
