# monoplane_embed_shaders(TARGET target SOURCES a.vert b.frag ...)
# Compiles GLSL with glslc at build time into SPIR-V words that a generated header embeds, so the
# executable carries its shaders. A shader a.vert becomes <build>/shaders/<dir>/a.vert.spv.inc,
# included as `static const uint32_t kWords[] = {#include "a.vert.spv.inc"};`.
function(monoplane_embed_shaders)
  cmake_parse_arguments(ARG "" "TARGET" "SOURCES" ${ARGN})
  foreach(src ${ARG_SOURCES})
    get_filename_component(name ${src} NAME)
    monoplane_embed_shader_variant(TARGET ${ARG_TARGET} SOURCE ${src} NAME ${name})
  endforeach()
endfunction()

# monoplane_embed_shader_variant(TARGET target SOURCE a.frag NAME a_gs.frag [DEFINES X Y]
#                                [SPIRV spv1.3])
# Compiles SOURCE with -D for each of DEFINES into NAME.spv.inc: also the variants of a shader that
# differ only in preprocessor switches (e.g. single-pass stereo), without a file for each. SPIRV
# picks an older SPIR-V version than Vulkan 1.3's, where a construct's capability differs by
# version (gl_Layer in a vertex shader: an extension's capability before SPIR-V 1.5).
function(monoplane_embed_shader_variant)
  cmake_parse_arguments(ARG "" "TARGET;SOURCE;NAME;SPIRV" "DEFINES" ${ARGN})
  file(RELATIVE_PATH rel_dir ${PROJECT_SOURCE_DIR} ${CMAKE_CURRENT_SOURCE_DIR})
  set(out_dir ${PROJECT_BINARY_DIR}/shaders/${rel_dir})
  file(MAKE_DIRECTORY ${out_dir})
  set(out ${out_dir}/${ARG_NAME}.spv.inc)
  set(variant_flags "")
  foreach(define ${ARG_DEFINES})
    list(APPEND variant_flags -D${define})
  endforeach()
  if(ARG_SPIRV)
    list(APPEND variant_flags --target-spv=${ARG_SPIRV})
  endif()
  add_custom_command(
    OUTPUT ${out}
    COMMAND Vulkan::glslc --target-env=vulkan1.3 -O -Werror -mfmt=num ${variant_flags}
            -I ${PROJECT_SOURCE_DIR} -MD -MF ${out}.d
            -o ${out} ${CMAKE_CURRENT_SOURCE_DIR}/${ARG_SOURCE}
    DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/${ARG_SOURCE}
    DEPFILE ${out}.d
    COMMENT "glslc ${rel_dir}/${ARG_NAME}"
    VERBATIM)
  target_sources(${ARG_TARGET} PRIVATE ${out})
  target_include_directories(${ARG_TARGET} PRIVATE ${out_dir})
endfunction()
