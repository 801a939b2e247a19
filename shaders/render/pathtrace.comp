// Reference path tracer (shaders/render/path_tracer.glsl): next-event estimation and BSDF sampling by MIS.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "render/path_tracer.glsl"
