// The implementations of Debian's header-only model readers, compiled once here with the options shadelab
// reads with (libtinyobjloader-dev, libtinygltf-dev; the same headers in the native and the browser build,
// which cannot link Debian's shared libraries). Their warnings are theirs: this file alone is compiled with
// -w (CMakeLists.txt, web/CMakeLists.txt).
#define TINYOBJLOADER_USE_DOUBLE // coordinates read as written (model_obj.cpp defines it too)
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>

// glTF's images are not read (shadelab draws no textures): no stb_image, no external image files.
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>
