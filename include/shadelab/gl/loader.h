// The one GL loader (glad, generated at build time). Every backend feeds it its own getProcAddress; no
// shadelab code calls a gl* symbol from a system library directly (if libGL preceded libOSMesa on the link
// line, such calls would silently do nothing under OSMesa).
#pragma once

#include <functional>
#include <string>

namespace shadelab::gl {

using ProcAddressFn = void (*(*)(const char*))();

// Loads every entry point for the context current on this thread. Throws RuntimeError naming `backend`
// when the context offers less than OpenGL 3.3 core.
void loadGl(ProcAddressFn getProcAddress, const char* backend);

// GL_RENDERER and GL_VERSION of the current context, e.g. "llvmpipe (LLVM 15.0.6, 256 bits), 4.5 (Core...)".
std::string rendererString();

// Throws RuntimeError naming `stage` if glGetError reports an error.
void checkGlError(const char* stage);

// Waits until the GPU has finished every command issued so far (for timing).
void finish();

// Routes KHR_debug messages of the current (debug) context to `sink`; returns false where the context
// offers no KHR_debug. The sink must outlive the context.
bool enableDebugOutput(std::function<void(const std::string& message)>* sink);

} // namespace shadelab::gl
