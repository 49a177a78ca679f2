// Shader programs, built from shaders/*.glsl with the version, the variant's #defines and #line prepended
// (no #version in the files). A variant is either the "uber" program of a shading mode × lighting model
// (light counts and types as uniforms, one loop) or a program specialized to one scene's light set-up:
// counts per light type as compile-time constants, and no attenuation, specular or ambient code where the
// scene has none (DESIGN §3 unchanged: the same equation with the absent terms left out).
#pragma once

#include <string>

#include "shadelab/gl/handles.h"
#include "shadelab/lighting.h"
#include "shadelab/scene.h"

namespace shadelab::gl {

struct ProgramVariant {
    ShadingMode shading = ShadingMode::Phong;
    LightingModel lighting = LightingModel::BlinnPhong;
    bool specialized = false;
    // Flat shading only: shared vertices and a geometry shader instead of three vertices per face.
    bool flatGeometryShader = false;
    // Specialized programs only:
    int directional = 0, point = 0, spot = 0; // lights of each type
    bool ambient = true;                      // some light's I_a is non-zero
    bool attenuation = true;                  // some point or spot light's attenuation is not (1, 0, 0)
    bool specular = true;                     // some object's k_s and some light's I_s are non-zero

    static ProgramVariant uber(ShadingMode shading, LightingModel lighting);
    // The scene's specialized variant, or its uber variant when `specialize` is false.
    static ProgramVariant forScene(const Scene& scene, bool specialize);

    // "phong/blinn-phong" (uber) or "phong/blinn-phong+d1p2s0-ambient-attenuation" (specialized; the
    // terms left out are listed): the spelling of logs, benchmarks and test names.
    std::string name() const;
    std::string defines() const; // the #define lines the variant compiles with
    bool operator==(const ProgramVariant&) const = default;
    // NOLINTNEXTLINE(modernize-use-nullptr): clang-tidy 14 misreads the defaulted comparison's own 0
    auto operator<=>(const ProgramVariant&) const = default;
};

// Compiles and links the variant. A failed compile or link throws RuntimeError with the stage, the
// variant name and the driver log; a non-empty log of a successful compile is printed to stderr.
Program buildProgram(const ProgramVariant& variant);

// The overlay's line program (shaders/lines.*.glsl): position and colour attributes (locations 0 and 1),
// uniform uClipFromSpace. Throws RuntimeError as buildProgram does.
Program buildLineProgram();

} // namespace shadelab::gl
