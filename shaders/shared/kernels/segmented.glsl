// Segmented arrays (host/vk/segmented_buffer.h, shaders/common/segmented_arrays.glsl): the specialization
// constant that says every segmented array a kernel binds has one segment. vk::ComputeKernel picks
// the pipeline per dispatch from the tables it has bound (SegmentedBuffer::segmentsAddressedBy);
// true makes PHOTON_AT / UINT_AT index segment 0 directly, without the table's shift and mask
// (docs/benchmarks.md "One-segment maps").
#ifndef VKP_KERNELS_SEGMENTED_GLSL
#define VKP_KERNELS_SEGMENTED_GLSL
#include "shared/compat.glsl"
SHARED_BEGIN

const uint kSingleSegmentId = 5u;  // bool, default false: any number of segments (4 is main's kSceneBvhTexelsId)

SHARED_END
#endif
