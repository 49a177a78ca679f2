// The one GL loader (glad, generated at build time). Every backend feeds it its own getProcAddress; no
// shadelab code calls a gl* symbol from a system library directly (if libGL preceded libOSMesa on the link
// line, such calls would silently do nothing under OSMesa).
#pragma once

#include <functional>
#include <string>
#include <string_view>

#include "shadelab/gl/api.h"

namespace shadelab::gl {

using ProcAddressFn = void (*(*)(const char*))();

// Loads every entry point of `api` for the context current on this thread. Throws RuntimeError naming
// `backend` when the context offers less than OpenGL 3.3 core or OpenGL ES 3.0.
void loadGl(ProcAddressFn getProcAddress, const char* backend, Api api = Api::Gl);

// What the loaded context can do beyond the common subset of OpenGL 3.3 core and OpenGL ES 3.0. The
// renderer asks here and refuses, naming the API, what the context lacks; it never substitutes.
struct Capabilities {
    Api api = Api::Gl;
    bool clipControl = false;      // glClipControl: desktop 4.5, or GL_EXT_clip_control on ES (reversed-Z)
    bool floatColorTargets = true; // RGBA32F renderbuffers: desktop 3.3, or EXT_color_buffer_float on ES
    bool geometryShaders = true;   // desktop only: GLSL ES 3.00 has no geometry stage
    bool sampleCounts = true;      // GL_SAMPLES_PASSED queries: desktop only (ES counts "any" samples)
    bool debugOutput = false;      // KHR_debug, or desktop 4.3
};
const Capabilities& capabilities();

// What precedes every GLSL source: "#version 330 core", or "#version 300 es" with highp defaults.
const char* glslHeader();

// The clip-space depth range: [-1, 1] (GL's default) or [0, 1] (reversed-Z). Throws RuntimeError naming
// `depthMode` and the API where [0, 1] is asked of a context without clip control.
void setClipDepthZeroToOne(bool zeroToOne, std::string_view depthMode);
// glClearDepth on desktop, glClearDepthf on ES.
void clearDepth(float depth);

// GL_RENDERER and GL_VERSION of the current context, e.g. "llvmpipe (LLVM 15.0.6, 256 bits), 4.5 (Core...)".
std::string rendererString();

// Throws RuntimeError naming `stage` if glGetError reports an error.
void checkGlError(const char* stage);

// Clears every pending glGetError flag (for errors a third-party library is known to leave; see panel.cpp).
void discardErrors();

// Waits until the GPU has finished every command issued so far (for timing).
void finish();

// Routes KHR_debug messages of the current (debug) context to `sink`; returns false where the context
// offers no KHR_debug. The sink must outlive the context.
bool enableDebugOutput(std::function<void(const std::string& message)>* sink);

} // namespace shadelab::gl
