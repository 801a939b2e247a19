// GLSL-only: incident light from one raster light (host/passes/raster_lights.h) at a point, as a
// delta LightSample so lightVisible() (scene_access.glsl) can trace the same shadow ray the
// reference does. Include after scene_access.glsl.
#ifndef VKP_RASTER_LIGHT_ACCESS_GLSL
#define VKP_RASTER_LIGHT_ACCESS_GLSL

#include "shared/shadow_volume.glsl"

LightSample rasterLightSample(GpuLight light, vec3 x) {
    LightSample ls;
    ls.delta = true;
    ls.pdf = 1.0f;
    if (light.type == kLightDirectional) {
        ls.wi = -light.direction;
        ls.distance = kInfinity;
        ls.position = vec3(0.0f);
        ls.radiance = light.intensity;
        return ls;
    }
    vec3 d = light.position - x;
    float dist2 = dot(d, d);
    ls.position = light.position;
    ls.distance = sqrt(dist2);
    ls.wi = d / ls.distance;
    ls.radiance = light.intensity / dist2;
    if (light.type == kLightSpot) {
        float t = clamp(dot(-ls.wi, light.direction) * light.spotScale + light.spotOffset, 0.0f, 1.0f);
        ls.radiance *= t * t;
    } else if (light.type == kLightAreaSample) {
        // A point sample of an emitter radiates intensity * |cos| to the sides it emits to.
        float cosLight = dot(-ls.wi, light.direction);
        if (cosLight < 0.0f && light.spotScale > 0.0f) cosLight = -cosLight;
        ls.radiance *= max(cosLight, 0.0f);
    }
    return ls;
}

#endif
