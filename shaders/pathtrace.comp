// Reference path tracer (shaders/path_tracer.glsl): next-event estimation and BSDF sampling by MIS.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "path_tracer.glsl"
