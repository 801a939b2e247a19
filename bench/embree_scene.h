// One Embree 3 scene of a vkphoton Scene's flattened world-space triangles (instances included),
// built with Embree's default (high-quality SAH) builder for static geometry: the CPU reference
// that bench/embree_bench (ray rates) and bench/textbook_bench (a textbook path tracer) trace.
#pragma once

#include <cstdint>
#include <limits>
#include <stdexcept>

#include <embree3/rtcore.h>
#include <glm/glm.hpp>

#include "scene/scene.h"

namespace vkp::bench {

class EmbreeScene {
public:
    explicit EmbreeScene(const Scene& scene) : EmbreeScene(flattenedTriangles(scene)) {}
    explicit EmbreeScene(const std::vector<Triangle>& triangles) : device_(rtcNewDevice(nullptr)) {
        if (!device_) throw std::runtime_error("rtcNewDevice failed");
        scene_ = rtcNewScene(device_);
        RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
            geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 3 * triangles.size()));
        auto* indices = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(
            geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), triangles.size()));
        for (size_t i = 0; i < triangles.size(); ++i)
            for (int k = 0; k < 3; ++k) {
                for (int c = 0; c < 3; ++c) vertices[9 * i + 3 * k + c] = triangles[i].p[k][c];
                indices[3 * i + k] = uint32_t(3 * i + k);
            }
        rtcCommitGeometry(geometry);
        rtcAttachGeometry(scene_, geometry);
        rtcReleaseGeometry(geometry);
        rtcCommitScene(scene_);
    }
    ~EmbreeScene() {
        rtcReleaseScene(scene_);
        rtcReleaseDevice(device_);
    }
    EmbreeScene(const EmbreeScene&) = delete;
    EmbreeScene& operator=(const EmbreeScene&) = delete;

    // Closest hit of one ray beyond `tnear`; returns false on a miss, else the distance, the
    // unit geometric normal (Embree's: the winding's, not faced towards the ray) and the triangle.
    bool intersect(const glm::vec3& origin, const glm::vec3& dir, float tnear, float& t, glm::vec3& normal,
                   uint32_t* triangle = nullptr) const {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRayHit rh{};
        rh.ray.org_x = origin.x, rh.ray.org_y = origin.y, rh.ray.org_z = origin.z;
        rh.ray.dir_x = dir.x, rh.ray.dir_y = dir.y, rh.ray.dir_z = dir.z;
        rh.ray.tnear = tnear;
        rh.ray.tfar = std::numeric_limits<float>::infinity();
        rh.ray.mask = ~0u;
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene_, &context, &rh);
        if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
        t = rh.ray.tfar;
        normal = glm::normalize(glm::vec3(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z));
        if (triangle) *triangle = rh.hit.primID;
        return true;
    }

    // True when something lies between tnear and tfar along the ray.
    bool occluded(const glm::vec3& origin, const glm::vec3& dir, float tnear, float tfar) const {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRay ray{};
        ray.org_x = origin.x, ray.org_y = origin.y, ray.org_z = origin.z;
        ray.dir_x = dir.x, ray.dir_y = dir.y, ray.dir_z = dir.z;
        ray.tnear = tnear;
        ray.tfar = tfar;
        ray.mask = ~0u;
        rtcOccluded1(scene_, &context, &ray);
        return ray.tfar < 0.0f;  // Embree sets tfar to -inf on a hit
    }

private:
    RTCDevice device_;
    RTCScene scene_ = nullptr;
};

}  // namespace vkp::bench
