# The sources of shadelab's libraries, relative to the repository's root: the one list the native build
# (CMakeLists.txt) and the browser build (web/CMakeLists.txt) read. Each reads them with its own root
# prepended (shadelab_sources).

# The core, no GL, in the lecture's order: the sphere, the camera, lighting, the scene and its files, the
# lessons, text and images, the ray cast and what is drawn from it.
set(SHADELAB_CORE_SOURCES
  src/sphere.cpp src/sphere_limits.cpp src/subdivision.cpp src/mesh_layout.cpp
  src/camera.cpp src/lighting.cpp
  src/scene.cpp src/scene_check.cpp src/scene_json.cpp src/scene_parse.cpp src/scene_write.cpp src/view.cpp
  src/lesson.cpp src/atomic_file.cpp src/text.cpp src/image.cpp src/font.cpp
  src/ray_cast.cpp src/probe.cpp src/overlay.cpp src/outside_view.cpp
  src/context/names.cpp)
# What only the native program needs: PNG files (libpng; the page hands the browser its pixels) and the
# analytic reference image (threads; the page checks against the native build instead).
set(SHADELAB_CORE_NATIVE_SOURCES src/png.cpp src/reference.cpp)
# GL: the loader, the objects, programs, meshes, the renderer, render targets and the teaching views.
set(SHADELAB_GL_SOURCES
  src/gl/loader.cpp src/gl/handles.cpp src/gl/program.cpp src/gl/program_variant.cpp src/gl/mesh.cpp
  src/gl/renderer.cpp src/gl/render_target.cpp src/gl/screen_pass.cpp src/gl/views.cpp)
# The demo's state, keys and texts and the scene flags (no GL), shared by the window and the page.
set(SHADELAB_DEMO_STATE_SOURCES
  src/app/demo/demo_state.cpp src/app/demo/demo_camera.cpp src/app/demo/demo_keys.cpp
  src/app/demo/demo_text.cpp src/app/demo/matrices_text.cpp src/app/demo/scene_flags.cpp)
# Drawing the demo's picture (GL), also shared by the window and the page.
set(SHADELAB_DEMO_DRAW_SOURCES src/app/demo/demo_draw.cpp)

# shadelab_sources(OUT LIST...): the named lists' files with `root` prepended.
function(shadelab_sources out root)
  set(files "")
  foreach(list IN LISTS ARGN)
    foreach(file IN LISTS ${list})
      list(APPEND files ${root}/${file})
    endforeach()
  endforeach()
  set(${out} ${files} PARENT_SCOPE)
endfunction()
