// Arrays split over several buffers (host/vk/segmented_buffer.h): a storage buffer holds the
// table, a header and the device address of each segment of 2^segmentShift elements; element i
// is items[i & segmentMask] of segment i >> segmentShift. Declare a table with
//   layout(std430, set = 0, binding = B) readonly buffer Name { SEGMENT_TABLE(PhotonSegment) } name;
// and reach its elements, to read or write, with SEGMENTED(name, i).
#ifndef VKP_SEGMENTED_GLSL
#define VKP_SEGMENTED_GLSL

#extension GL_EXT_buffer_reference : require

#include "shared/photon.glsl"

layout(buffer_reference, std430, buffer_reference_align = 16) buffer PhotonSegment { GpuPhoton items[]; };
layout(buffer_reference, std430, buffer_reference_align = 4) buffer UintSegment { uint items[]; };

#define SEGMENT_TABLE(Segment) uint segmentShift; uint segmentMask; uint segmentCount; uint segmentPad; Segment segments[];
#define SEGMENTED(table, i) table.segments[(i) >> table.segmentShift].items[(i) & table.segmentMask]

#endif
