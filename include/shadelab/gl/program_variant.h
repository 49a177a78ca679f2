// Which program draws a scene (gl/program.h builds it): the "uber" program of a shading mode × lighting
// model (light counts and types as uniforms, one loop), or a program specialized to one scene's light
// set-up — counts per light type as compile-time constants, and no attenuation, specular or ambient code
// where the scene has none (DESIGN §3 unchanged: the same equation with the absent terms left out) — and,
// further, to one object's values (its material times the lights' colours, the lights' attenuation and
// cones) as constants. A variant is the key of the renderer's program cache and gives the #define lines it
// compiles with, the constants shaders/lighting.glsl shares with src/shading/lighting.cpp among them.
#pragma once

#include <string>

#include "shadelab/scene/scene.h"
#include "shadelab/shading/lighting.h"

namespace shadelab::gl {

// How far the renderer specializes its programs (docs/contributors.md "Leaving out what a scene does not
// need").
enum class Specialization {
    None,   // the uber program of each shading mode × lighting model: the baseline and the cross-check
    Lights, // to the scene's light set-up; values stay uniforms, so the window recompiles nothing when a
            // colour, a light's attenuation or the shininess changes
    Values, // and to each drawn object's values, compiled in as constants: a program per object's values
            // (`shadelab render` and `bench`). llvmpipe reads every uniform component a fragment shader
            // uses with a gather of all eight lanes, constants with none (bench/README.md).
};

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
    bool viewerAtInfinity = false;            // an orthographic projection: v is the constant +z
    // Exact shading only: toon's quantized lighting on the exact sphere (the error view's answer for toon).
    bool exactToon = false;
    // The NDC view (mesh shading modes): gl_Position is the observer's, and each fragment outside the
    // camera's clip volume (|x|, |y|, |z| > w, or w <= 0) is discarded, as the clipper would remove it.
    bool ndcView = false;
    // An open surface (the teapot, a mesh not marked closed; DESIGN §3 "Open surfaces"): a back face is lit
    // with its normal turned towards the viewer (TWO_SIDED). A define, not a uniform, as the modes above
    // are: a closed object's program is the same source as before, and only a scene that mixes closed and
    // open objects builds a second program.
    bool twoSided = false;
    // Exact shading of the teapot (EXACT_PATCHES): a proxy mesh whose fragments refine the ray's hit on
    // their Bézier patch (shaders/exact_patch.*.glsl) instead of the sphere's proxy rectangle.
    bool exactPatches = false;
    // Mesh shading modes: alpha is uAlpha instead of 1 (OBJECT_ID_ALPHA), for a mesh object drawn as the
    // exact answer of the error view's compare pass (its exact shading is Phong of the mesh).
    bool objectIdAlpha = false;
    // Specialization::Values only: the #define lines that compile one object's values in (withValues);
    // empty otherwise. Every float is written so that it reads back as the same float.
    std::string values;

    static ProgramVariant uber(ShadingMode shading, LightingModel lighting);
    // The scene's specialized variant (to its light set-up), or its uber variant when `specialize` is false.
    static ProgramVariant forScene(const Scene& scene, bool specialize);
    // This specialized variant with `material`'s and the scene's lights' values compiled in (the floats
    // lightValues and ambientProduct give the uniforms otherwise), and the scene's toon bands.
    ProgramVariant withValues(const Scene& scene, const Material& material) const;

    // "phong/blinn-phong" (uber) or "phong/blinn-phong+d1p2s0-ambient-attenuation" (specialized; the
    // terms left out are listed, "+ortho" for a viewer at infinity, "+values" with values compiled in):
    // the spelling of logs, benchmarks and test names.
    std::string name() const;
    std::string defines() const; // the #define lines the variant compiles with
    bool operator==(const ProgramVariant&) const = default;
    // The order of the program cache, over every field. Not a defaulted <=>: the browser build's libc++
    // (LLVM 14) gives std::string none.
    bool operator<(const ProgramVariant& other) const;
};

} // namespace shadelab::gl
