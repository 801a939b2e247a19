// The item an invocation computes in a dispatch of one invocation per item (vk::Kernel::record):
// 1-D, or past the device's maxComputeWorkGroupCount[0] workgroups (4 M items of 64 on lavapipe)
// rows of workgroups, numbered row by row. Kernels that use it declare kRowsOfGroups in their
// interface (shaders/shared/kernels/); with 1-D dispatches it equals gl_GlobalInvocationID.x.
// A macro, not a function: gl_WorkGroupSize is only the kernel's size after its local_size
// declaration, which comes after the includes (in a function defined before it, glslang gives 1).
#ifndef VKP_ITEM_INDEX_GLSL
#define VKP_ITEM_INDEX_GLSL

#define itemIndex() (gl_GlobalInvocationID.x + gl_WorkGroupID.y * gl_NumWorkGroups.x * gl_WorkGroupSize.x)

#endif
