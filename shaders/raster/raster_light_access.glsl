// GLSL-only: incident light from one raster light (host/passes/raster_lights.h) at a point, as a
// delta LightSample so lightVisible() (scene_access.glsl) can trace the same shadow ray the
// reference does. Include after scene_access.glsl.
#ifndef VKP_RASTER_LIGHT_ACCESS_GLSL
#define VKP_RASTER_LIGHT_ACCESS_GLSL

#include "shared/shadow_volume.glsl"

LightSample rasterLightSample(GpuLight light, vec3 x) {
    LightSample ls = punctualLightSample(light, x);
    if (light.type == kLightAreaSample) {
        // A point sample of an emitter radiates intensity * |cos| to the sides it emits to.
        float cosLight = dot(-ls.wi, light.direction);
        if (cosLight < 0.0f && light.spotScale > 0.0f) cosLight = -cosLight;
        ls.radiance *= max(cosLight, 0.0f);
    }
    return ls;
}

#endif
