// Arrays split over several buffers (host/vk/segmented_buffer.h): a storage buffer holds the
// table, a header and the device address of each segment of 2^segmentShift elements; element i
// is items[i & segmentMask] of segment i >> segmentShift. Declare a table with
//   SEGMENTED_ARRAY(B, Name, name);
// and reach its elements, to read or write, with PHOTON_AT(name, i) or UINT_AT(name, i): macros
// that name i twice, so i must be free of side effects (no atomicAdd in it).
// Kernels are compiled twice (host/vk/compute_kernel.h): with kSingleSegment true, used by the
// dispatches whose bound arrays all have one segment (the common case: maps up to 4 M photons),
// the macros index segment 0, whose address is read once per invocation (SEGMENTED_ARRAY), and
// nothing of the table's header: the table read per access had made one-segment maps' grid
// builds 2-2.7x and nearest-photon lookups 1.3-1.7x slower (docs/benchmarks.md, "One-segment maps").
// Addresses are uvec2 (GL_EXT_buffer_reference_uvec2): an array of reference types in a block
// makes glslang declare RuntimeDescriptorArray, which the validation layer rejects.
#ifndef VKP_SEGMENTED_GLSL
#define VKP_SEGMENTED_GLSL

#extension GL_EXT_buffer_reference : require
#extension GL_EXT_buffer_reference_uvec2 : require

#include "shared/kernels/segmented.glsl"
#include "shared/photon.glsl"

layout(buffer_reference, std430, buffer_reference_align = 16) buffer PhotonSegment { GpuPhoton items[]; };
layout(buffer_reference, std430, buffer_reference_align = 4) buffer UintSegment { uint items[]; };

layout(constant_id = kSingleSegmentId) const bool kSingleSegment = false;

#define SEGMENT_TABLE uint segmentShift; uint segmentMask; uint segmentCount; uint segmentPad; uvec2 segments[];
// The table `name` at binding B of set 0, and its segment 0's address, read once per invocation
// at the start of main (a global's initializer): the one-segment form reads nothing else of it.
#define SEGMENTED_ARRAY(B, Block, name) \
    layout(std430, set = 0, binding = B) readonly buffer Block { SEGMENT_TABLE } name; \
    uvec2 name##Segment0 = name.segments[0]
#define SEGMENT_ADDRESS_(table, i) (kSingleSegment ? table##Segment0 : table.segments[(i) >> table.segmentShift])
#define INDEX_IN_SEGMENT_(table, i) (kSingleSegment ? (i) : (i) & table.segmentMask)
#define PHOTON_AT(table, i) PhotonSegment(SEGMENT_ADDRESS_(table, i)).items[INDEX_IN_SEGMENT_(table, i)]
#define UINT_AT(table, i) UintSegment(SEGMENT_ADDRESS_(table, i)).items[INDEX_IN_SEGMENT_(table, i)]

#endif
