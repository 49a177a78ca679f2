// The lighting equations of DESIGN §3 on the CPU, in double. shaders/lighting.glsl is the GLSL mirror of
// this file: a change to one is a change to both. The analytic reference (reference.h) shades with it.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <string_view>
#include <utility>

#include <glm/glm.hpp>

namespace shadelab {

// Modes are typed enums with one spelling everywhere: CLI, scene files, keys, test names, report rows.
// Exact is no mesh: each sphere or ellipsoid ray-cast per pixel and lit like Phong shading, the n → ∞ limit
// the mesh modes are measured against (the analytic reference, drawn in real time).
enum class ShadingMode { Flat, Gouraud, Phong, Toon, Exact };
enum class LightingModel { Phong, BlinnPhong };
enum class LightType { Ambient, Directional, Point, Spot };
// "term": which of the lighting sum's three terms a picture shows (DESIGN §3's k_a·I_a, the diffuse and the
// specular sums), each as the shading mode evaluates it; all is the whole sum.
enum class LightingTerm { All, Ambient, Diffuse, Specular };

// The modes that shade the subdivided mesh: what the report, the showcase and the error view compare.
inline constexpr std::array kShadingModes = {ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong,
                                             ShadingMode::Toon};
// Every spelling `shading` accepts.
inline constexpr std::array kAllShadingModes = {ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong,
                                                ShadingMode::Toon, ShadingMode::Exact};
inline constexpr std::array kLightingModels = {LightingModel::Phong, LightingModel::BlinnPhong};
inline constexpr std::array kLightTypes = {LightType::Ambient, LightType::Directional, LightType::Point,
                                           LightType::Spot};
inline constexpr std::array kLightingTerms = {LightingTerm::All, LightingTerm::Ambient, LightingTerm::Diffuse,
                                              LightingTerm::Specular};

std::string_view toString(ShadingMode mode);    // "flat" | "gouraud" | "phong" | "toon" | "exact"
std::string_view toString(LightingModel model); // "phong" | "blinn-phong"
std::string_view toString(LightType type);      // "ambient" | "directional" | "point" | "spot"
std::string_view toString(LightingTerm term);   // "all" | "ambient" | "diffuse" | "specular"
std::optional<ShadingMode> parseShadingMode(std::string_view text);
std::optional<LightingModel> parseLightingModel(std::string_view text);

inline constexpr int kMaxLights = 8;
inline constexpr int kToonBands = 4; // default diffuse bands in toon shading
inline constexpr int kMinToonBands = 2, kMaxToonBands = 16;
inline constexpr double kToonHighlight = 0.5; // spec above this is a full highlight, below it none

struct Material {
    glm::dvec3 ambient{0.1, 0.1, 0.1};
    glm::dvec3 diffuse{0.7, 0.2, 0.2};
    glm::dvec3 specular{1, 1, 1};
    double shininess = 32; // α for Phong, β for Blinn-Phong; >= 1
    bool operator==(const Material&) const = default;
};

// The material with the coefficients of every term but `term` set to 0: what the renderer draws for a
// "term" (the shaders evaluate their one equation, and the other terms vanish from it). The CPU reference
// does not use it: it takes the term from shadeTerms' three sums (ShadeOptions::term).
Material onlyTerm(const Material& material, LightingTerm term);

struct Light {
    LightType type = LightType::Point;
    glm::dvec3 ambient{0, 0, 0};
    glm::dvec3 diffuse{1, 1, 1};
    glm::dvec3 specular{1, 1, 1};
    glm::dvec3 position{0, 0, 0};    // point, spot
    glm::dvec3 direction{0, 0, -1};  // directional, spot: the direction the light travels (non-zero)
    double cutoffDeg = 90;           // spot
    double exponent = 0;             // spot
    glm::dvec3 attenuation{1, 0, 0}; // a, b, c of 1/(a + b·t + c·t²); point, spot
    bool operator==(const Light&) const = default;
};

// Moves a light's position and direction into the space `m` maps to (positions by m, directions by its
// upper 3×3). Used to bring world-space lights into view space.
Light transformLight(const Light& light, const glm::dmat4& m);

// A point to shade. All vectors in one space (view space in shadelab); `normal` and `toViewer` unit length.
struct SurfacePoint {
    glm::dvec3 position;
    glm::dvec3 normal;
    glm::dvec3 toViewer;
    bool operator==(const SurfacePoint&) const = default;
};

struct ShadeOptions {
    LightingModel model = LightingModel::BlinnPhong;
    bool toon = false;
    int toonBands = kToonBands;
    LightingTerm term = LightingTerm::All; // what shade() returns: the whole sum or one of its terms
};

// The three sums of DESIGN §3's equation, each over every light and not yet clamped: Σ k_a·I_a,
// Σ att·spot·k_d·I_d·max(l·n,0) and Σ att·spot·[l·n > 0]·k_s·I_s·spec (toon: the quantized terms). The demo's
// probe shows them one by one; shade() is their sum.
struct LightTerms {
    glm::dvec3 ambient{0.0}, diffuse{0.0}, specular{0.0};
    glm::dvec3 total() const { return ambient + diffuse + specular; }
    glm::dvec3 of(LightingTerm term) const; // one term, or total() for All
    bool operator==(const LightTerms&) const = default;
};
LightTerms shadeTerms(const SurfacePoint& point, const Material& material, std::span<const Light> lights,
                      ShadeOptions options);

// I = Σ_lights [k_a·I_a + att·spot·(k_d·I_d·max(l·n,0) + [l·n > 0]·k_s·I_s·spec)], not yet clamped; with
// options.term, that term of it alone.
glm::dvec3 shade(const SurfacePoint& point, const Material& material, std::span<const Light> lights,
                 ShadeOptions options);

// DESIGN §3's guards, one value each for C++ and GLSL (gl/program_variant.cpp hands them to the shaders as
// #defines, with the LightType codes):
// a vector whose largest component is below kTinyComponent is not normalized (its fallback is used);
inline constexpr double kTinyComponent = 1e-30;
// the attenuation's denominator a + b·t + c·t² is at least this, so a light on the surface with a = 0
// stays finite;
inline constexpr double kMinAttenuationDenominator = 1e-12;
// GLSL's normalizeBounded (a vector the CPU has bounded, |v| <= 3) normalizes no |v|² below this.
inline constexpr double kMinLengthSquared = 1e-36;

// The steps of one light's term, in the order shadeTerms takes them and shaders/lighting.glsl's functions
// of the same names do:
// DESIGN §3's v: the unit vector from `positionView` towards the viewer — towards the eye under perspective,
// +z under orthographic projection (the eye at infinity, back along the parallel rays). A viewer exactly
// on the surface sees it head-on: v falls back to the normal (as l does for a light on the surface).
glm::dvec3 toViewer(const glm::dvec3& positionView, const glm::dvec3& normalView, bool orthographic);
// The unit vector from `point` towards `light` (for a directional light: against its direction) and the
// distance to it (0 for directional and ambient lights): DESIGN §3's l and t.
std::pair<glm::dvec3, double> toLight(const Light& light, const SurfacePoint& point);
// att = 1/(a + b·t + c·t²) for point and spot lights, 1 for the others.
double attenuation(const Light& light, double t);
// spot = max(−l·d, 0)^e inside the cone, 0 outside; 1 for other lights.
double spotFactor(const Light& light, const glm::dvec3& l);
// spec = max(v·r, 0)^α (Phong) or max(n·h, 0)^β (Blinn-Phong), the exponent at least 1.
double specular(const SurfacePoint& point, const glm::dvec3& l, double shininess, LightingModel model);
// The vector the specular term measures against: r = −l + 2(l·n)n (Phong) or h = normalize(v + l)
// (Blinn-Phong).
glm::dvec3 specularVector(const SurfacePoint& point, const glm::dvec3& l, LightingModel model);

// Colours and intensities are capped at kMaxColorComponent before they are lit, in C++ and (on upload) in
// GLSL alike: a product of two stays below 1e36, inside float's range, so no term becomes Inf and no
// Inf·0 becomes NaN on the way to the clamp. The cap changes no pixel a valid scene can show: a term
// that large is 1 after clamping either way.
inline constexpr double kMaxColorComponent = 1e18;
glm::dvec3 capColor(const glm::dvec3& color);

// Clamp to [0, 1] (a NaN becomes 0): what reaches a pixel.
glm::dvec3 clampColor(const glm::dvec3& color);

// normalize(v), or `fallback` when |v| is too small to normalize (DESIGN §3: normalize nothing that can be
// 0).
glm::dvec3 safeNormalize(const glm::dvec3& v, const glm::dvec3& fallback);

// `v` scaled to unit length whatever its magnitude (1e-300 or 1e300): divided by its largest component
// first. Directions (of lights, of spots) are scale-free; `v` must be finite and non-zero.
glm::dvec3 unitDirection(const glm::dvec3& v);

// What one light gives the shaders for one material, each value rounded to float once: the same floats
// whether they are set as uniforms (gl/renderer.cpp) or compiled in (gl::ProgramVariant::withValues). All
// finite: colours are capped (capColor), so the products stay inside float's range, and an attenuation or
// exponent beyond it becomes the largest float (an Inf has no GLSL literal, and in pow(1, Inf) it would
// give NaN where the equation gives 1).
struct LightValues {
    glm::vec3 ambientProduct{0}, diffuseProduct{0}, specularProduct{0}; // k_a·I_a, k_d·I_d, k_s·I_s
    glm::vec3 attenuation{1, 0, 0};                                     // a, b, c
    float cosCutoff = 0, exponent = 0;                                  // spot lights
};
LightValues lightValues(const Light& light, const Material& material);
// k_a·ΣI_a over all lights: a specialized program's one ambient term.
glm::vec3 ambientProduct(std::span<const Light> lights, const Material& material);
// The material's exponent: at least 1 (DESIGN §3's guard), at most the largest float.
float shininessValue(const Material& material);

} // namespace shadelab
