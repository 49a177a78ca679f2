// What a run will need in memory, estimated before any of it is spent, against what the process may have:
// the address-space limit (ulimit -v, RLIMIT_AS) and the machine's physical memory. docs/ci-engineers.md
// "Memory".
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "app/check/memory_check.h" // checkMemoryBudget, kProcessBaselineBytes, mebibytes
#include "shadelab/scene/scene.h"

namespace shadelab::app {

// Address space the GL stack itself takes before drawing anything, measured with Mesa 22.3 llvmpipe on
// 2 cores (EGL and OSMesa): a 64x64 render fails or crashes inside Mesa (exit 139) at random below about
// 640 MiB of `ulimit -v`, and succeeded in every run from 660 MB up.
inline constexpr double kGlBaselineBytes = 640.0 * 1024 * 1024;

// Bytes one render of `scene` adds on top of the baseline: the offscreen colour and depth buffers, the
// read-back and PNG rows, and the GPU copies of every distinct mesh (a sphere or a teapot at a level, a
// model; vertex and index buffers).
double renderBytes(const Scene& scene);
// Bytes `shadelab reference` of `scene` takes in all (no GL: the CPU ray cast and its images).
double referenceBytes(const Scene& scene);

// "512x512": a scene's image size, as the budget's messages name a render.
std::string sizeText(const Scene& scene);

} // namespace shadelab::app
