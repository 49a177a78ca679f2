# The sources of shadelab's libraries, relative to the repository's root: the one list the native build
# (CMakeLists.txt) and the browser build (web/CMakeLists.txt) read. Each reads them with its own root
# prepended (shadelab_sources).

# The light library shadelab_check, no GL and no scene: io (atomic writes, printable text) and image
# (pixels, the labels' font); the page's build compiles these into its own program too.
set(SHADELAB_IMAGE_SOURCES
  src/io/atomic_file.cpp src/io/output_path.cpp src/io/numbered_files.cpp src/io/text.cpp
  src/image/image.cpp src/image/font.cpp)
# What only the native programs need of it: PNG files (libpng; the page hands the browser its pixels).
set(SHADELAB_IMAGE_NATIVE_SOURCES src/image/png.cpp)
# The regression kit on top of them (native only): the image metrics and the judgement against limits
# (src/compare), and the compare and review commands (src/app/check; their mains are the executables').
set(SHADELAB_CHECK_SOURCES
  src/compare/judge.cpp src/compare/ssim.cpp src/compare/perceptual.cpp src/compare/heatmap.cpp
  src/app/check/compare_command.cpp src/app/check/check_cli.cpp src/app/check/memory_check.cpp
  src/app/check/expectations.cpp src/app/check/review.cpp src/app/check/review_files.cpp src/app/check/review_run.cpp
  src/app/check/review_json.cpp src/app/check/junit.cpp
  src/app/check/review_page.cpp)

# The core, no GL, a folder for each stage of the pipeline and in the order they depend on each other:
# geometry (the subdivided sphere), shading (the lighting equations and their value types), scene (the
# camera and view volume, the scene's values, files, flags and "auto" level, lessons), then what reads a
# whole scene: exact (the ray cast, the reference image, the probe) and diagram (the overlay's lines, the
# outside view's drawing, a point's stages); and the context names. It links the light library (above).
set(SHADELAB_CORE_SOURCES
  src/geometry/sphere.cpp src/geometry/sphere_limits.cpp src/geometry/subdivision.cpp src/geometry/mesh_layout.cpp
  src/geometry/teapot.cpp src/geometry/teapot_data.cpp
  src/shading/lighting.cpp
  src/scene/camera.cpp src/scene/observer.cpp src/scene/auto_level.cpp src/scene/view.cpp src/scene/scene.cpp src/scene/scene_check.cpp
  src/scene/scene_shapes.cpp src/scene/model.cpp src/scene/model_obj.cpp src/scene/model_gltf.cpp src/scene/model_libraries.cpp
  src/scene/scene_limits.cpp src/scene/scene_messages.cpp src/scene/scene_json.cpp src/scene/scene_parse.cpp
  src/scene/scene_write.cpp src/scene/scene_flags.cpp src/scene/lesson.cpp src/scene/slide_name.cpp
  src/exact/ray_cast.cpp src/exact/probe.cpp src/exact/patch_cast.cpp src/exact/mesh_cast.cpp
  src/diagram/overlay.cpp src/diagram/outside_view.cpp src/diagram/point_stages.cpp
  src/diagram/mesh_overlay.cpp
  src/context/names.cpp)
# What only the native program needs: the analytic reference image (threads; the page checks against the
# native build instead).
set(SHADELAB_CORE_NATIVE_SOURCES src/exact/reference.cpp)
# GL: the loader, the objects, programs, meshes, the renderer, render targets and the teaching views.
set(SHADELAB_GL_SOURCES
  src/gl/loader.cpp src/gl/handles.cpp src/gl/program.cpp src/gl/program_variant.cpp src/gl/mesh.cpp
  src/gl/renderer.cpp src/gl/scene_draw.cpp src/gl/scene_draw_lines.cpp src/gl/render_target.cpp src/gl/screen_pass.cpp
  src/gl/scene_draw_exact.cpp
  src/gl/views.cpp src/gl/views_split.cpp src/gl/views_observed.cpp src/gl/views_profile.cpp)
# The demo's state, keys and texts (no GL), shared by the window and the page.
set(SHADELAB_DEMO_STATE_SOURCES
  src/app/demo/demo_state.cpp src/app/demo/demo_camera.cpp src/app/demo/demo_keys.cpp
  src/app/demo/demo_text.cpp src/app/demo/probe_text.cpp src/app/demo/matrices_text.cpp
  src/app/demo/demo_presets.cpp src/app/demo/demo_edits.cpp src/app/demo/view_explanations.cpp
  src/app/demo/lesson_player.cpp src/app/demo/probe_cache.cpp src/app/demo/presentation_images.cpp src/app/demo/scene_setters.cpp)
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
