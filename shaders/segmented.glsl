// Arrays split over several buffers (host/vk/segmented_buffer.h): a storage buffer holds the
// table, a header and the device address of each segment of 2^segmentShift elements; element i
// is items[i & segmentMask] of segment i >> segmentShift. Declare a table with
//   layout(std430, set = 0, binding = B) readonly buffer Name { SEGMENT_TABLE } name;
// and reach its elements, to read or write, with PHOTON_AT(name, i) or UINT_AT(name, i): macros
// that name i twice, so i must be free of side effects (no atomicAdd in it).
// Addresses are uvec2 (GL_EXT_buffer_reference_uvec2): an array of reference types in a block
// makes glslang declare RuntimeDescriptorArray, which the validation layer rejects.
#ifndef VKP_SEGMENTED_GLSL
#define VKP_SEGMENTED_GLSL

#extension GL_EXT_buffer_reference : require
#extension GL_EXT_buffer_reference_uvec2 : require

#include "shared/photon.glsl"

layout(buffer_reference, std430, buffer_reference_align = 16) buffer PhotonSegment { GpuPhoton items[]; };
layout(buffer_reference, std430, buffer_reference_align = 4) buffer UintSegment { uint items[]; };

#define SEGMENT_TABLE uint segmentShift; uint segmentMask; uint segmentCount; uint segmentPad; uvec2 segments[];
#define PHOTON_AT(table, i) PhotonSegment(table.segments[(i) >> table.segmentShift]).items[(i) & table.segmentMask]
#define UINT_AT(table, i) UintSegment(table.segments[(i) >> table.segmentShift]).items[(i) & table.segmentMask]

#endif
