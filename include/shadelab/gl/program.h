// Shader programs, built from shaders/*.glsl with the version, the variant's #defines and #line prepended
// (no #version in the files). A variant is either the "uber" program of a shading mode × lighting model
// (light counts and types as uniforms, one loop) or a program specialized to one scene's light set-up:
// counts per light type as compile-time constants, and no attenuation, specular or ambient code where the
// scene has none (DESIGN §3 unchanged: the same equation with the absent terms left out) — and, further,
// to one object's values (its material times the lights' colours, the lights' attenuation and cones) as
// constants.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

#include "shadelab/gl/handles.h"
#include "shadelab/lighting.h"
#include "shadelab/scene.h"

namespace shadelab::gl {

// How far the renderer specializes its programs (README "Leaving out what a scene does not need").
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

// What one light gives the shaders for one material, each value rounded to float once: the same floats
// whether they are set as uniforms (renderer.cpp) or compiled in (ProgramVariant::withValues). All finite:
// colours are capped (capColor), so the products stay inside float's range, and an attenuation or
// exponent beyond it becomes the largest float (an Inf has no GLSL literal, and in pow(1, Inf) it would
// give NaN where the equation gives 1).
struct LightValues {
    glm::vec3 ambientProduct{0}, diffuseProduct{0}, specularProduct{0}; // k_a·I_a, k_d·I_d, k_s·I_s
    glm::vec3 attenuation{1, 0, 0};                                     // a, b, c
    float cosCutoff = 0, exponent = 0;                                  // spot lights
};
LightValues lightValues(const Light& light, const Material& material);
// k_a·ΣI_a over all lights: a specialized program's one ambient term.
glm::vec3 ambientProduct(const std::vector<Light>& lights, const Material& material);
// The material's exponent: at least 1 (DESIGN §3's guard), at most the largest float.
float shininessValue(const Material& material);

// Where a surface program keeps its uniforms, looked up once when it is built (not by name every frame).
// −1 marks a uniform the variant does not declare (an absent light type, the ambient sum of an
// ambient-free variant) or that the compiler removed as unused; glUniform* ignores −1.
// The colours are products with the drawn object's material (k_a·I_a, k_d·I_d, k_s·I_s: set per object).
struct LightLocations {
    int type = -1, ambientProduct = -1; // uber program only
    int diffuseProduct = -1, specularProduct = -1, positionView = -1, directionView = -1, cosCutoff = -1,
        exponent = -1, attenuation = -1;
};
struct SurfaceLocations {
    int clipFromObject = -1, viewFromObject = -1, normalViewFromObject = -1, handedness = -1;
    int cameraClipFromObject = -1; // the NDC view: the camera's M_proj·M_cam·M, for the clip-volume test
    // Exact shading only (shaders/exact.*.glsl): the proxy rectangle and what casting a pixel's ray needs.
    int ndcRect = -1, viewport = -1, nearRect = -1, nearFar = -1, objectFromView = -1, centerView = -1,
        clipFromView = -1, depthZeroToOne = -1, alpha = -1;
    int shininess = -1, orthographic = -1, toonBands = -1, toonBandWidth = -1, lightCount = -1;
    int ambientProduct = -1; // specialized: k_a·ΣI_a
    // Uber program: lights[0] holds uLights[0..MAX_LIGHTS). Specialized: lights[1], [2], [3] hold the
    // directional, point and spot arrays (indexed by the LIGHT_* codes of shaders/lighting.glsl).
    std::array<std::vector<LightLocations>, 4> lights;
};

// A linked surface program and its uniform locations. Throws RuntimeError naming the uniform when one that
// every variant uses (the clip transform) is missing: a misspelt name is a loud failure, not a no-op.
struct SurfaceProgram {
    SurfaceProgram(Program linked, const ProgramVariant& variant);
    Program program;
    SurfaceLocations at;
};

// Compiles and links the variant. A failed compile or link throws RuntimeError with the stage, the
// variant name and the driver log; a non-empty log of a successful compile is printed to stderr.
Program buildProgram(const ProgramVariant& variant);

// A program from two GLSL bodies with the context's version line prepended (gl::glslHeader) and
// attribute locations given in the source (layout(location = N)); `name` labels its messages. Throws
// RuntimeError with the stage and the driver log, as buildProgram does.
Program buildProgramFromBodies(const std::string& name, std::string_view vertexBody,
                               std::string_view fragmentBody);

// The overlay's line program (shaders/lines.*.glsl): position and colour attributes (locations 0 and 1),
// uniform uClipFromSpace. Throws RuntimeError as buildProgram does.
Program buildLineProgram();

} // namespace shadelab::gl
