# Compiles GLSL entry points to SPIR-V with glslangValidator (depfiles make header edits rebuild
# what includes them), validates them with spirv-val, and embeds the words into a static library
# as a name -> std::span<const uint32_t> table (see host/vk/shader_registry.h).
find_program(GLSLANG_VALIDATOR glslangValidator REQUIRED)
find_program(SPIRV_VAL spirv-val REQUIRED)

function(vkphoton_embed_shaders target)
  set(embedded_sources)
  set(names)
  foreach(src IN LISTS ARGN)
    get_filename_component(file_name ${src} NAME)
    string(MAKE_C_IDENTIFIER ${file_name} ident)
    set(spv ${CMAKE_CURRENT_BINARY_DIR}/shaders/${file_name}.spv)
    set(cpp ${CMAKE_CURRENT_BINARY_DIR}/shaders/${file_name}.cpp)
    set(dep ${CMAKE_CURRENT_BINARY_DIR}/shaders/${file_name}.d)
    add_custom_command(
      OUTPUT ${spv}
      COMMAND ${GLSLANG_VALIDATOR} -V --target-env vulkan1.3 -g0
              -I${PROJECT_SOURCE_DIR}/shaders --depfile ${dep} -o ${spv} ${src}
      COMMAND ${SPIRV_VAL} --target-env vulkan1.3 ${spv}
      DEPENDS ${src}
      DEPFILE ${dep}
      COMMENT "GLSL ${file_name}"
      VERBATIM)
    add_custom_command(
      OUTPUT ${cpp}
      COMMAND ${CMAKE_COMMAND} -DSPV=${spv} -DOUT=${cpp} -DIDENT=${ident} -DNAME=${file_name}
              -P ${PROJECT_SOURCE_DIR}/cmake/EmbedSpirv.cmake
      DEPENDS ${spv} ${PROJECT_SOURCE_DIR}/cmake/EmbedSpirv.cmake
      VERBATIM)
    list(APPEND embedded_sources ${cpp})
    list(APPEND names ${ident})
  endforeach()
  set(table ${CMAKE_CURRENT_BINARY_DIR}/shaders/${target}_table.cpp)
  set(content "#include <cstdint>\n#include <span>\n#include <string_view>\n#include <utility>\n")
  foreach(ident IN LISTS names)
    string(APPEND content "namespace vkp::embedded { extern const std::pair<std::string_view, std::span<const uint32_t>> ${ident}; }\n")
  endforeach()
  # Pointers, not copies: the entries live in other translation units, and only their addresses
  # are constant at static-initialisation time.
  string(APPEND content "namespace vkp::embedded {\nextern const std::pair<std::string_view, std::span<const uint32_t>>* const ${target}_table[] = {\n")
  foreach(ident IN LISTS names)
    string(APPEND content "  &${ident},\n")
  endforeach()
  string(APPEND content "  nullptr};\n}\n")
  file(CONFIGURE OUTPUT ${table} CONTENT "${content}")
  add_library(${target} STATIC ${embedded_sources} ${table})
endfunction()
