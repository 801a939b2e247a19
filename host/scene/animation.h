// glTF 2.0 animations (docs/animation.md): node translation / rotation / scale channels sampled
// with LINEAR (slerp, the short way, for rotations), STEP and CUBICSPLINE interpolation, clamped
// outside their key range. SceneAnimation turns a time into the local transforms of the animated
// nodes, which the loader's GltfSceneSource flattens into that moment's Scene.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace tinygltf { class Model; }

namespace vkp {

enum class AnimationPath { Translation, Rotation, Scale };
enum class Interpolation { Linear, Step, CubicSpline };

// A channel with its sampler's keys. values: one per key (LINEAR, STEP) or three per key
// (CUBICSPLINE: in-tangent, value, out-tangent); xyz for translation and scale, a quaternion
// (x, y, z, w: glTF's order) for rotation.
struct AnimationChannel {
    int node = -1;
    AnimationPath path = AnimationPath::Translation;
    Interpolation interpolation = Interpolation::Linear;
    std::vector<float> times;       // strictly increasing, finite
    std::vector<glm::vec4> values;
};

struct Animation {
    std::string name;
    std::vector<AnimationChannel> channels;
    float start = 0.0f;  // first and last key time over all channels
    float end = 0.0f;
};

// The channel's value at time t (seconds): the first key's value before the first key, the
// last one's after the last. Rotations come back normalised; LINEAR rotations are slerped along
// the shorter arc; CUBICSPLINE tangents are scaled by the key interval (glTF 2.0, Appendix C).
glm::dvec4 sampleChannel(const AnimationChannel& channel, double t);

// Spherical linear interpolation of unit quaternions (x, y, z, w) the short way (q1 negated when
// the two are more than 180 degrees apart on the 4-sphere).
glm::dvec4 slerpShortest(glm::dvec4 q0, glm::dvec4 q1, double s);

// A node's translation, rotation (x, y, z, w) and scale.
struct NodeTrs {
    glm::dvec3 translation{0.0};
    glm::dvec4 rotation{0.0, 0.0, 0.0, 1.0};
    glm::dvec3 scale{1.0};
    glm::dmat4 matrix() const;  // T * R * S
};

using WarningSink = std::function<void(const std::string&)>;

class SceneAnimation {
public:
    // Reads and checks every animation of the model: throws vkp::InputError naming the element
    // ("animations[0].samplers[1]: ...") for mismatched key counts, non-increasing or non-finite
    // times, NaN keys, channels targeting missing nodes or nodes given as a matrix, unknown paths
    // or interpolations. Warns through `warn` about `weights` channels (ignored: morph targets
    // keep their static weights) and channels without a target node (ignored, as glTF says).
    // Skins need nothing here: joints are nodes, and the loader skins with their animated transforms.
    SceneAnimation(const tinygltf::Model& model, const WarningSink& warn);

    const std::vector<Animation>& animations() const { return m_animations; }
    bool empty() const { return m_animations.empty(); }
    // --animation N: play only animation N (-1: all together). Throws InputError when absent.
    void select(int index);
    int selected() const { return m_selected; }
    // Key range of the selected animation(s); 0..0 without any.
    double startTime() const;
    double endTime() const;
    // Local transforms at time t for every node of the model: the animated TRS (static TRS where a
    // component is not animated) for nodes the selected animation(s) target, nullopt elsewhere.
    std::vector<std::optional<glm::dmat4>> localTransforms(double t) const;

private:
    std::vector<NodeTrs> m_rest;  // the nodes' static TRS
    std::vector<Animation> m_animations;
    int m_selected = -1;
};

}  // namespace vkp
