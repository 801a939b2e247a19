#include "scene/animation.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <glm/gtc/quaternion.hpp>
#include <tiny_gltf.h>

#include "scene/gltf_accessors.h"
#include "util/errors.h"

namespace vkp {
namespace {

[[noreturn]] void fail(const std::string& element, const std::string& what) {
    throw InputError(fmt::format("{}: {}", element, what));
}

glm::dvec4 normalizeQuat(const glm::dvec4& q) {
    const double length = glm::length(q);
    return length > 0.0 ? q / length : glm::dvec4(0.0, 0.0, 0.0, 1.0);
}

// Cubic Hermite spline between p0 and p1 with tangents m0, m1 already scaled by the interval.
glm::dvec4 hermite(const glm::dvec4& p0, const glm::dvec4& m0, const glm::dvec4& p1, const glm::dvec4& m1, double s) {
    const double s2 = s * s, s3 = s2 * s;
    return (2.0 * s3 - 3.0 * s2 + 1.0) * p0 + (s3 - 2.0 * s2 + s) * m0 + (-2.0 * s3 + 3.0 * s2) * p1 + (s3 - s2) * m1;
}

// Reads a sampler's keys into `channel` and checks them.
void readSampler(const tinygltf::Model& model, const tinygltf::AnimationSampler& sampler, AnimationChannel& channel,
                 const std::string& element) {
    if (sampler.interpolation == "LINEAR" || sampler.interpolation.empty()) channel.interpolation = Interpolation::Linear;
    else if (sampler.interpolation == "STEP") channel.interpolation = Interpolation::Step;
    else if (sampler.interpolation == "CUBICSPLINE") channel.interpolation = Interpolation::CubicSpline;
    else fail(element + ".interpolation", fmt::format("unknown interpolation \"{}\" (LINEAR, STEP or CUBICSPLINE)",
                                                      sampler.interpolation));
    try {
        channel.times = readScalarAccessor(model, sampler.input);
    } catch (const InputError& e) {
        fail(element + ".input", e.what());
    }
    try {
        if (channel.path == AnimationPath::Rotation) {
            channel.values = readVec4Accessor(model, sampler.output);
        } else {
            for (const glm::vec3& v : readVec3Accessor(model, sampler.output)) channel.values.emplace_back(v, 0.0f);
        }
    } catch (const InputError& e) {
        fail(element + ".output", e.what());
    }
    if (channel.times.empty()) fail(element + ".input", "has no keys");
    for (size_t i = 0; i < channel.times.size(); ++i) {
        if (!std::isfinite(channel.times[i]))
            fail(element + ".input", fmt::format("key time {} is NaN or infinite", i));
        if (i > 0 && !(channel.times[i] > channel.times[i - 1]))
            fail(element + ".input", fmt::format("key times must increase strictly: key {} at {} follows {}", i,
                                                 channel.times[i], channel.times[i - 1]));
    }
    const size_t perKey = channel.interpolation == Interpolation::CubicSpline ? 3 : 1;
    if (channel.values.size() != perKey * channel.times.size())
        fail(element, fmt::format("{} output values for {} key times; {} needs {}", channel.values.size(),
                                  channel.times.size(), sampler.interpolation.empty() ? "LINEAR" : sampler.interpolation,
                                  perKey * channel.times.size()));
    for (size_t i = 0; i < channel.values.size(); ++i) {
        const glm::vec4& v = channel.values[i];
        if (!std::isfinite(v.x + v.y + v.z + v.w))
            fail(element + ".output", fmt::format("value {} is NaN or infinite", i));
        // In-tangents and out-tangents of a rotation may be anything finite; values must rotate.
        if (channel.path == AnimationPath::Rotation && (perKey == 1 || i % 3 == 1) && !(glm::length(glm::dvec4(v)) > 0.0))
            fail(element + ".output", fmt::format("rotation {} is not a unit quaternion (zero length)", i / perKey));
    }
}

}  // namespace

glm::dmat4 NodeTrs::matrix() const {
    glm::dmat4 t(1.0), s(1.0);
    t[3] = glm::dvec4(translation, 1.0);
    const glm::dvec4 q = normalizeQuat(rotation);
    const glm::dmat4 r = glm::mat4_cast(glm::dquat(q.w, q.x, q.y, q.z));
    for (int k = 0; k < 3; ++k) s[k][k] = scale[k];
    return t * r * s;
}

glm::dvec4 slerpShortest(glm::dvec4 q0, glm::dvec4 q1, double s) {
    q0 = normalizeQuat(q0);
    q1 = normalizeQuat(q1);
    double d = glm::dot(q0, q1);
    if (d < 0.0) {  // the other cover of the same rotation is nearer
        q1 = -q1;
        d = -d;
    }
    if (d > 0.9995) return normalizeQuat(q0 + s * (q1 - q0));  // nearly parallel: lerp is exact enough
    const double angle = std::acos(std::min(d, 1.0));
    const double sinAngle = std::sin(angle);
    return normalizeQuat((std::sin((1.0 - s) * angle) / sinAngle) * q0 + (std::sin(s * angle) / sinAngle) * q1);
}

glm::dvec4 sampleChannel(const AnimationChannel& c, double t) {
    const bool cubic = c.interpolation == Interpolation::CubicSpline;
    const auto value = [&](size_t key) { return glm::dvec4(c.values[cubic ? 3 * key + 1 : key]); };
    const bool rotation = c.path == AnimationPath::Rotation;
    const auto finish = [&](const glm::dvec4& v) { return rotation ? normalizeQuat(v) : v; };
    const size_t n = c.times.size();
    if (n == 1 || t <= c.times.front()) return finish(value(0));
    if (t >= c.times.back()) return finish(value(n - 1));
    // The key interval [k, k + 1) holding t.
    const size_t k = size_t(std::upper_bound(c.times.begin(), c.times.end(), float(t)) - c.times.begin()) - 1;
    const size_t key = std::min(k, n - 2);
    const double t0 = c.times[key], t1 = c.times[key + 1];
    const double interval = t1 - t0;
    const double s = std::clamp((t - t0) / interval, 0.0, 1.0);
    switch (c.interpolation) {
    case Interpolation::Step: return finish(value(t >= t1 ? key + 1 : key));
    case Interpolation::Linear:
        return rotation ? slerpShortest(value(key), value(key + 1), s) : (1.0 - s) * value(key) + s * value(key + 1);
    case Interpolation::CubicSpline: {
        const glm::dvec4 m0 = interval * glm::dvec4(c.values[3 * key + 2]);      // out-tangent of key
        const glm::dvec4 m1 = interval * glm::dvec4(c.values[3 * (key + 1)]);    // in-tangent of key + 1
        return finish(hermite(value(key), m0, value(key + 1), m1, s));
    }
    }
    return finish(value(key));
}

SceneAnimation::SceneAnimation(const tinygltf::Model& model, const WarningSink& warn) {
    m_rest.resize(model.nodes.size());
    for (size_t i = 0; i < model.nodes.size(); ++i) {
        const tinygltf::Node& node = model.nodes[i];
        NodeTrs& trs = m_rest[i];
        if (node.translation.size() == 3) trs.translation = {node.translation[0], node.translation[1], node.translation[2]};
        if (node.rotation.size() == 4) trs.rotation = {node.rotation[0], node.rotation[1], node.rotation[2], node.rotation[3]};
        if (node.scale.size() == 3) trs.scale = {node.scale[0], node.scale[1], node.scale[2]};
    }
    size_t weightChannels = 0;
    for (size_t a = 0; a < model.animations.size(); ++a) {
        const tinygltf::Animation& source = model.animations[a];
        const std::string element = fmt::format("animations[{}]", a);
        Animation animation;
        animation.name = source.name.empty() ? element : source.name;
        bool any = false;
        for (size_t c = 0; c < source.channels.size(); ++c) {
            const tinygltf::AnimationChannel& channel = source.channels[c];
            const std::string channelElement = fmt::format("{}.channels[{}]", element, c);
            AnimationChannel out;
            if (channel.target_path == "translation") out.path = AnimationPath::Translation;
            else if (channel.target_path == "rotation") out.path = AnimationPath::Rotation;
            else if (channel.target_path == "scale") out.path = AnimationPath::Scale;
            else if (channel.target_path == "weights") {
                ++weightChannels;
                continue;
            } else {
                fail(channelElement + ".target.path",
                     fmt::format("unknown path \"{}\" (translation, rotation, scale or weights)", channel.target_path));
            }
            if (channel.target_node < 0) {
                warn(fmt::format("{}: no target node; the channel is ignored", channelElement));
                continue;
            }
            if (size_t(channel.target_node) >= model.nodes.size())
                fail(channelElement + ".target.node",
                     fmt::format("nodes[{}] does not exist (the file has {} nodes)", channel.target_node, model.nodes.size()));
            if (!model.nodes[channel.target_node].matrix.empty())
                fail(channelElement + ".target.node",
                     fmt::format("nodes[{}] has a matrix; glTF animates only nodes given as translation/rotation/scale",
                                 channel.target_node));
            out.node = channel.target_node;
            if (channel.sampler < 0 || size_t(channel.sampler) >= source.samplers.size())
                fail(channelElement + ".sampler",
                     fmt::format("samplers[{}] does not exist (the animation has {})", channel.sampler, source.samplers.size()));
            readSampler(model, source.samplers[channel.sampler], out,
                        fmt::format("{}.samplers[{}]", element, channel.sampler));
            animation.start = any ? std::min(animation.start, out.times.front()) : out.times.front();
            animation.end = any ? std::max(animation.end, out.times.back()) : out.times.back();
            any = true;
            animation.channels.push_back(std::move(out));
        }
        m_animations.push_back(std::move(animation));
    }
    if (weightChannels > 0)
        warn(fmt::format("{} `weights` animation channel(s) ignored: morph targets keep their static weights (the "
                         "node's or the mesh's `weights`) in every frame",
                         weightChannels));
}

void SceneAnimation::select(int index) {
    if (index >= 0 && size_t(index) >= m_animations.size())
        throw InputError(fmt::format("--animation {}: the file has {} animation(s)", index, m_animations.size()));
    m_selected = index;
}

double SceneAnimation::startTime() const {
    double start = 0.0;
    bool any = false;
    for (size_t i = 0; i < m_animations.size(); ++i)
        if ((m_selected < 0 || int(i) == m_selected) && !m_animations[i].channels.empty()) {
            start = any ? std::min(start, double(m_animations[i].start)) : m_animations[i].start;
            any = true;
        }
    return start;
}

double SceneAnimation::endTime() const {
    double end = 0.0;
    for (size_t i = 0; i < m_animations.size(); ++i)
        if ((m_selected < 0 || int(i) == m_selected) && !m_animations[i].channels.empty())
            end = std::max(end, double(m_animations[i].end));
    return end;
}

std::vector<std::optional<glm::dmat4>> SceneAnimation::localTransforms(double t) const {
    std::vector<std::optional<NodeTrs>> posed(m_rest.size());
    for (size_t i = 0; i < m_animations.size(); ++i) {
        if (m_selected >= 0 && int(i) != m_selected) continue;
        for (const AnimationChannel& channel : m_animations[i].channels) {
            std::optional<NodeTrs>& trs = posed[channel.node];
            if (!trs) trs = m_rest[channel.node];
            const glm::dvec4 v = sampleChannel(channel, t);
            switch (channel.path) {
            case AnimationPath::Translation: trs->translation = glm::dvec3(v); break;
            case AnimationPath::Rotation: trs->rotation = v; break;
            case AnimationPath::Scale: trs->scale = glm::dvec3(v); break;
            }
        }
    }
    std::vector<std::optional<glm::dmat4>> out(m_rest.size());
    for (size_t i = 0; i < posed.size(); ++i)
        if (posed[i]) out[i] = posed[i]->matrix();
    return out;
}

}  // namespace vkp
