# The GL loader, generated at build time from Debian's python3-glad (offline: --reproducible uses the
# gl.xml the package ships): desktop OpenGL core and OpenGL ES 3.0 merged into one header and one set of
# entry points (gladLoadGL or gladLoadGLES2 fills them). To regenerate by hand, the exact command is:
#   glad --api gl:core=4.5,gles2=3.0 --merge --extensions <GLAD_EXTENSIONS below> \
#        --out-path <build>/generated/glad --reproducible --quiet c
# No loader of its own (no --loader): every context backend feeds it its own getProcAddress
# (eglGetProcAddress, OSMesaGetProcAddress, glfwGetProcAddress) through gl/loader.h.
set(GLAD_DIR ${SHADELAB_GENERATED}/glad)
# KHR_debug on both; ES: clip control (reversed-Z), float colour targets, timer queries where present.
set(GLAD_EXTENSIONS
    GL_KHR_debug,GL_ARB_timer_query,GL_EXT_clip_control,GL_EXT_color_buffer_float,GL_EXT_disjoint_timer_query)
add_custom_command(
  OUTPUT ${GLAD_DIR}/src/gl.c ${GLAD_DIR}/include/glad/gl.h
  COMMAND ${GLAD_EXECUTABLE} --api gl:core=4.5,gles2=3.0 --merge --extensions ${GLAD_EXTENSIONS}
          --out-path ${GLAD_DIR} --reproducible --quiet c
  COMMENT "Generating the GL loader with glad"
  DEPENDS ${CMAKE_CURRENT_LIST_FILE}
  VERBATIM)
add_library(glad_gl STATIC ${GLAD_DIR}/src/gl.c)
target_include_directories(glad_gl SYSTEM PUBLIC ${GLAD_DIR}/include)
set_target_properties(glad_gl PROPERTIES POSITION_INDEPENDENT_CODE ON)
