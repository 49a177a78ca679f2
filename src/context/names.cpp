// The spellings of the context vocabularies (shadelab/context/context.h, shadelab/gl/api.h): GL-free, so the
// command line's help and parsing (and its fuzzer) need no GL library.
#include "shadelab/context/context.h"
#include "shadelab/vocabulary.h"

namespace shadelab {

std::string_view toString(Api api) {
    return api == Api::Gl ? "gl" : "gles";
}

std::string_view displayName(Api api) {
    return api == Api::Gl ? "OpenGL 3.3 core" : "OpenGL ES 3.0";
}

std::optional<Api> parseApi(std::string_view text) {
    return parseName(text, kApis);
}

std::string_view toString(Backend backend) {
    return backend == Backend::Egl ? "egl" : "osmesa";
}

std::optional<Backend> parseBackend(std::string_view text) {
    return parseName(text, kBackends);
}

} // namespace shadelab
