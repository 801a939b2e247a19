// glTF 2.0 (.gltf / .glb) loading through tinygltf into a flattened vkp::Scene.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "scene/animation.h"
#include "scene/scene.h"

namespace vkp {

// Limits that keep a hostile file from exhausting memory.
struct GltfLimits {
    uint64_t maxFileBytes = 2ull << 30;       // the .gltf/.glb itself and each external buffer
    uint32_t maxImageDimension = 16384;       // width and height of any texture
    uint64_t maxImagePixels = 64ull << 20;    // width * height of any texture
    uint64_t maxTotalImagePixels = 256ull << 20;  // all images of the file together (1 GiB as RGBA8)
    uint64_t maxTriangles = 1ull << 26;
    // What the device and the machine can take, checked before any vertex data is decoded
    // (counted from the accessors' counts, every reference of a mesh included). Exceeding them
    // is a RuntimeError (exit 1): the file is fine, the machine is too small.
    uint64_t deviceMaxTriangles = UINT64_MAX;  // deviceTriangleLimit() of the render's device
    uint64_t maxMemoryBytes = UINT64_MAX;      // --max-memory, else the memory available
    // Not a limit: which glTF scene to load (--scene); -1: the file's `scene`, else scene 0.
    int sceneIndex = -1;
    // Not a limit: the KHR_materials_variants variant to render (--variant), by name; "": every
    // primitive's own material. A name the file does not list is an InputError naming the ones it does.
    std::string materialVariant;
    // Not a limit: a glTF mesh drawn at least twice (nodes, EXT_mesh_gpu_instancing) with at least
    // this many triangles is kept once as an instanced mesh (docs/bvh.md) instead of copied per
    // drawing; 0: every repeated mesh, UINT64_MAX: none (animated nodes' meshes always are).
    uint64_t instanceMinTriangles = 64;
    // Not a limit: every mesh that can be instanced is (`vkphoton view`: any node may be moved in
    // place; emissive and skinned meshes stay flattened).
    bool instanceEveryMesh = false;
};

// Host memory the loader, the BVH build and the upload need per triangle at their peak, for the
// estimate against GltfLimits::maxMemoryBytes: 545 bytes measured (peak RSS less the 108 MB of
// an empty run, 1.0 M and 1.67 M triangles on lavapipe), with a margin.
constexpr uint64_t kHostBytesPerTriangle = 600;

// The range of world-space coordinates the renderer's single-precision arithmetic handles
// (docs/scene-format.md, "Scale"): every vertex, light and camera within +-kMaxCoordinate, a
// scene at least kMinSceneExtent across (the ray offsets scale with it; below, products of
// distances underflow floats) and no farther from the origin than kMaxOffsetPerExtent times its
// extent; radiometric intensities up to kMaxRadiometric.
constexpr double kMaxCoordinate = 1.0e8;
constexpr double kMinSceneExtent = 1.0e-5;
constexpr double kMaxOffsetPerExtent = 1.0e2;
constexpr double kMaxRadiometric = 1.0e20;
constexpr double kMaxTotalPower = 1.0e30;

// Loads limits.sceneIndex, else the default scene (or scene 0) of a glTF file. Throws vkp::InputError with a message of
// the form "FILE: ELEMENT: what is wrong" (e.g. "box.gltf: meshes[2].primitives[0]: ...") for
// any bad input; never crashes on malformed files. Buffer and image URIs that are absolute, leave
// the file's folder (".."), or contain shell expansion characters are refused.
Scene loadGltf(const std::filesystem::path& path, const GltfLimits& limits = {});

// A glTF file parsed once and kept (materials and textures converted), whose scene is flattened
// again for each moment of its animations (docs/animation.md): no reparsing per frame. Errors as
// loadGltf's; bad animations are InputErrors at construction.
class GltfSceneSource {
public:
    GltfSceneSource(const std::filesystem::path& path, const GltfLimits& limits = {});
    ~GltfSceneSource();
    GltfSceneSource(const GltfSceneSource&) = delete;
    GltfSceneSource& operator=(const GltfSceneSource&) = delete;

    SceneAnimation& animation() { return *m_animation; }
    // World-space translations per node index (shorter than the node list: the rest 0): a node's
    // world transform becomes translate(offset) * its world transform, and its children follow
    // (`vkphoton view` moves nodes so).
    using NodeOffsets = std::vector<glm::dvec3>;
    // The scene with the selected animation(s) sampled at `seconds`, nodes moved by `offsets`.
    Scene sceneAt(double seconds, const NodeOffsets* offsets = nullptr);
    // The scene as loadGltf gives it: every node at its static TRS (no animation applied).
    Scene stillScene(const NodeOffsets* offsets = nullptr);
    // The index of the first node named `name`, or -1; a node's name ("nodes[i]" when unnamed).
    int findNode(const std::string& name) const;
    std::string nodeName(int index) const;

private:
    class State;
    std::filesystem::path m_path;
    std::unique_ptr<State> m_state;
    std::optional<SceneAnimation> m_animation;
};

}  // namespace vkp
