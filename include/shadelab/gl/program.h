// Shader programs: one per shading mode × lighting model, built from shaders/*.glsl with the version,
// the variant's #defines and #line prepended (no #version in the files).
#pragma once

#include <string>

#include "shadelab/gl/handles.h"
#include "shadelab/lighting.h"

namespace shadelab::gl {

struct ProgramVariant {
    ShadingMode shading = ShadingMode::Phong;
    LightingModel lighting = LightingModel::BlinnPhong;
    std::string name() const; // e.g. "phong/blinn-phong": the spelling of logs and test names
    auto operator<=>(const ProgramVariant&) const = default;
};

// Compiles and links the variant. A failed compile or link throws RuntimeError with the stage, the
// variant name and the driver log; a non-empty log of a successful compile is printed to stderr.
Program buildProgram(const ProgramVariant& variant);

} // namespace shadelab::gl
