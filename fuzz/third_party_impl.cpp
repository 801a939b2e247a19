// tinygltf's and stb_image's implementations compiled into the fuzzer, so the sanitizers and the
// coverage instrumentation see inside them (the normal build links Debian's shared libraries).
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>  // includes <stb_image.h> and <stb_image_write.h> (include path /usr/include/stb)
