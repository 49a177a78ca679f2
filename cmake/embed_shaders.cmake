# Embeds shaders/*.glsl in the binary at build time: the .glsl files stay the source of truth and nothing
# reads them from the working directory at run time. Output: ${SHADELAB_GENERATED}/shaders.cpp, which
# defines shadelab::gl::embeddedShader(name) (declared in src/gl/shader_sources.h).
file(GLOB SHADELAB_SHADER_FILES CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/shaders/*.glsl)
set(SHADELAB_SHADERS_CPP ${SHADELAB_GENERATED}/shaders.cpp)
add_custom_command(
  OUTPUT ${SHADELAB_SHADERS_CPP}
  COMMAND ${CMAKE_COMMAND} -DOUTPUT=${SHADELAB_SHADERS_CPP} "-DINPUTS=${SHADELAB_SHADER_FILES}"
          -P ${CMAKE_SOURCE_DIR}/cmake/embed_shaders_run.cmake
  DEPENDS ${SHADELAB_SHADER_FILES} ${CMAKE_SOURCE_DIR}/cmake/embed_shaders_run.cmake
  COMMENT "Embedding shaders"
  VERBATIM)
