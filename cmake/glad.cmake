# The GL loader, generated at build time from Debian's python3-glad (offline: --reproducible uses the
# gl.xml the package ships). To regenerate by hand, the exact command is:
#   glad --api gl:core=4.5 --extensions GL_KHR_debug,GL_ARB_timer_query \
#        --out-path <build>/generated/glad --reproducible --quiet c
# No loader of its own (no --loader): every context backend feeds it its own getProcAddress
# (eglGetProcAddress, OSMesaGetProcAddress, glfwGetProcAddress) through gl/loader.h.
set(GLAD_DIR ${SHADELAB_GENERATED}/glad)
add_custom_command(
  OUTPUT ${GLAD_DIR}/src/gl.c ${GLAD_DIR}/include/glad/gl.h
  COMMAND ${GLAD_EXECUTABLE} --api gl:core=4.5 --extensions GL_KHR_debug,GL_ARB_timer_query
          --out-path ${GLAD_DIR} --reproducible --quiet c
  COMMENT "Generating the GL loader with glad"
  VERBATIM)
add_library(glad_gl STATIC ${GLAD_DIR}/src/gl.c)
target_include_directories(glad_gl SYSTEM PUBLIC ${GLAD_DIR}/include)
set_target_properties(glad_gl PROPERTIES POSITION_INDEPENDENT_CODE ON)
