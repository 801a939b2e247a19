// The common subset of GLSL and C++/GLM. Every file in shaders/shared/ includes this first, so the
// same source compiles as a shader and as C++ (the host build is the reference the GPU must match).
//
// Rules for shared code: float literals with `f`, only single-component swizzles, assign struct
// fields instead of constructing structs, no recursion, no bool in buffers, mark every function
// INLINE and pass out-parameters as INOUT(T) (or OUT(T) where GLSL should not copy them in).
#ifndef VKP_COMPAT_GLSL
#define VKP_COMPAT_GLSL

#ifdef __cplusplus
#include <cstdint>
#include <glm/glm.hpp>
#include <glm/gtc/packing.hpp>
#define INLINE inline
#define INOUT(T) T&
#define OUT(T) T&
#define INOUT_ARRAY(T, name, N) T name[N]
#define IN_ARRAY(T, name, N) const T name[N]
#define SHARED_BEGIN namespace vkp::gpu { using namespace glm;
#define SHARED_END }
#define STATIC_ASSERT_SIZE(T, N) static_assert(sizeof(T) == (N), #T ": GLSL vs C++ size mismatch");
#else
#define INLINE
#define INOUT(T) inout T
#define OUT(T) out T
#define INOUT_ARRAY(T, name, N) inout T name[N]
#define IN_ARRAY(T, name, N) T name[N]
#define SHARED_BEGIN
#define SHARED_END
#define STATIC_ASSERT_SIZE(T, N)
#endif

#endif
