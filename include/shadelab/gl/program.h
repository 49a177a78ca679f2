// Shader programs, built from shaders/*.glsl with the version, a variant's #defines
// (gl/program_variant.h) and #line prepended (no #version in the files), and the uniform locations of a
// surface program, found once when it is built.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "shadelab/gl/handles.h"
#include "shadelab/gl/program_variant.h"

namespace shadelab::gl {

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

// The uniform buffer binding point of the teapot's control points (shaders/exact_patch.frag.glsl).
inline constexpr unsigned kTeapotPatchesBinding = 0;

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
