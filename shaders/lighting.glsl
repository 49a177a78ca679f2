// The lighting equations of DESIGN §3: the GLSL mirror of src/shading/lighting.cpp (change both together). The steps
// of a light's term have the C++ names — toViewer, toLight, attenuation, spotFactor, specular — and the
// guards are C++'s constants. Prepended to both stages of every program. All vectors are in view space; the
// viewer is at the origin.
// Defines it responds to, each written by gl::ProgramVariant::defines (src/gl/program_variant.cpp):
//   MAX_LIGHTS            size of the uber program's light array
//   TINY_COMPONENT, MIN_ATTENUATION_DENOMINATOR, MIN_LENGTH_SQUARED  DESIGN §3's guards (lighting.h's
//                         kTinyComponent, kMinAttenuationDenominator, kMinLengthSquared)
//   LIGHT_AMBIENT, LIGHT_DIRECTIONAL, LIGHT_POINT, LIGHT_SPOT  the LightType codes of uLights[i].type
//   TOON_HIGHLIGHT        kToonHighlight
//   LIGHTING_BLINN_PHONG  Blinn-Phong specular max(n·h,0)^β; otherwise Phong max(v·r,0)^α
//   SHADING_TOON          diffuse quantized into uToonBands bands, highlight thresholded at TOON_HIGHLIGHT
//   SPECIALIZED           a program for one scene's light set-up (ProgramVariant in gl/program_variant.h), with
//     NUM_DIRECTIONAL, NUM_POINT, NUM_SPOT  light counts per type as compile-time constants
//     HAS_AMBIENT       some light has a non-zero ambient term (summed on the CPU: uAmbientProduct)
//     HAS_ATTENUATION   some point or spot light has attenuation other than (1, 0, 0)
//     HAS_SPECULAR      some object's k_s and some light's I_s are non-zero
//     NEEDS_NORMAL      some light is not ambient (ambient-only scenes read no normal attribute)
//     VIEWER_AT_INFINITY  an orthographic projection: v = +z everywhere, a constant (else the local viewer)
//     VALUES_COMPILED_IN  the drawn object's values as constants, not uniforms (Specialization::Values),
//       with SHININESS, AMBIENT_PRODUCT (HAS_AMBIENT), TOON_BANDS and TOON_BAND_WIDTH (toon) defined as
//       literals and DIRECTIONAL_VALUES, POINT_VALUES, SPOT_VALUES as LightValues[](...) lists; the lights'
//       view-space positions and directions stay uniforms (they move with the camera); SHININESS_INTEGER
//       as well where the shininess is a whole number up to 2047 (x^n by squaring)
//   VERTEX_STAGE, FRAGMENT_STAGE, GEOMETRY_STAGE  which stage this copy is compiled into (set by the loader)
//   Without SPECIALIZED: the uber program — counts and types as uniforms, one loop over all lights.
// The colours arrive with the object's material multiplied in on the CPU (k_a·I_a, k_d·I_d, k_s·I_s, per
// object and light): formed here they would be products of uniforms evaluated per fragment, and llvmpipe
// reads every uniform component a fragment shader uses with a bounds-checked gather of all eight lanes
// (bench/README.md "What llvmpipe makes of the fragment shader"); with VALUES_COMPILED_IN they are
// constants, and none is gathered.

struct Light {
    int type;             // uber program only
    vec3 ambientProduct;  // k_a·I_a; uber program only (specialized programs sum it into uAmbientProduct)
    vec3 diffuseProduct;  // k_d·I_d
    vec3 specularProduct; // k_s·I_s
    vec3 positionView;
    vec3 directionView; // unit; the direction the light travels
    float cosCutoff;
    float exponent;
    vec3 attenuation;   // a, b, c of 1/(a + b·t + c·t²)
};

// A light's values for the drawn object, compiled in (VALUES_COMPILED_IN): Light's fields of those names.
struct LightValues {
    vec3 diffuseProduct;
    vec3 specularProduct;
    vec3 attenuation;
    float cosCutoff;
    float exponent;
};

Light withValues(Light geometry, LightValues values) {
    geometry.diffuseProduct = values.diffuseProduct;
    geometry.specularProduct = values.specularProduct;
    geometry.attenuation = values.attenuation;
    geometry.cosCutoff = values.cosCutoff;
    geometry.exponent = values.exponent;
    return geometry;
}

#ifndef SPECIALIZED
#define NEEDS_NORMAL 1
#define HAS_AMBIENT 1
#define HAS_ATTENUATION 1
#define HAS_SPECULAR 1
uniform Light uLights[MAX_LIGHTS];
uniform int uLightCount;
#else
#if HAS_AMBIENT && !defined(VALUES_COMPILED_IN)
uniform vec3 uAmbientProduct; // k_a·Σ I_a over all lights
#define AMBIENT_PRODUCT uAmbientProduct
#endif
// One array of light geometry per type, and with VALUES_COMPILED_IN one of its values for the object;
// LIGHT_OF(geometry, values, i) is light i of a type with both (without compiled-in values, the uniform
// already holds them and the values array is neither declared nor named after expansion).
#ifdef VALUES_COMPILED_IN
#define VALUES_ARRAY(name, count, list) const LightValues name[count] = list;
#define LIGHT_OF(geometry, values, i) withValues(geometry[i], values[i])
#else
#define VALUES_ARRAY(name, count, list)
#define LIGHT_OF(geometry, values, i) geometry[i]
#endif
#if NUM_DIRECTIONAL > 0
uniform Light uDirectionalLights[NUM_DIRECTIONAL];
VALUES_ARRAY(kDirectionalValues, NUM_DIRECTIONAL, DIRECTIONAL_VALUES)
#endif
#if NUM_POINT > 0
uniform Light uPointLights[NUM_POINT];
VALUES_ARRAY(kPointValues, NUM_POINT, POINT_VALUES)
#endif
#if NUM_SPOT > 0
uniform Light uSpotLights[NUM_SPOT];
VALUES_ARRAY(kSpotValues, NUM_SPOT, SPOT_VALUES)
#endif
#endif

// Per-fragment lighting in a specialized program: each positional light's p_light − p (points first, then
// spots) comes from the vertex stage, interpolated. It is affine in p, so interpolating it is as exact as
// interpolating p itself; and the fragment stage no longer reads the light's position, three uniform
// components per light that llvmpipe would gather for every eight fragments (see the colours above).
#if defined(SPECIALIZED) && (defined(SHADING_PHONG) || defined(SHADING_TOON)) && !defined(SHADING_EXACT)
#if NUM_POINT + NUM_SPOT > 0
#define INTERPOLATED_TO_LIGHT
#if defined(VERTEX_STAGE)
out vec3 vToLightView[NUM_POINT + NUM_SPOT];
#elif defined(FRAGMENT_STAGE)
in vec3 vToLightView[NUM_POINT + NUM_SPOT];
#endif
#endif
#endif

#ifndef VALUES_COMPILED_IN
uniform float uShininess;    // >= 1: pow(0, 0) is undefined in GLSL
uniform float uToonBands;    // SHADING_TOON only
uniform float uToonBandWidth; // 1 / uToonBands, divided once on the CPU
#define SHININESS uShininess
#define TOON_BANDS uToonBands
#define TOON_BAND_WIDTH uToonBandWidth
#endif
#ifndef SPECIALIZED
uniform bool uOrthographic;  // parallel projection: the viewer direction is +z everywhere
#endif

// normalize(v), or the fallback where v is too short to normalize (DESIGN §3 guards), for a v of any finite
// magnitude (view-space positions reach 1e30): scaling by the largest component first keeps dot(v, v) from
// overflowing or underflowing float. One reciprocal, not three divisions, and a select, not a branch
// (measured with callgrind, bench/README.md "Where a frame's instructions go").
vec3 safeNormalize(vec3 v, vec3 fallback) {
    float largest = max(max(abs(v.x), abs(v.y)), abs(v.z));
    vec3 scaled = v * (1.0 / largest);
    vec3 unit = scaled * inversesqrt(dot(scaled, scaled));
    return largest > TINY_COMPONENT ? unit : fallback;
}

// normalize(v) for a v the CPU has bounded (|v| <= 3: an interpolated normal of the normal matrix that
// renderer.cpp divides by its largest entry), so dot(v, v) cannot overflow: only the too-short case needs
// a guard, and a plain normalize does the rest.
vec3 normalizeBounded(vec3 v, vec3 fallback) {
    float lengthSquared = dot(v, v);
    return lengthSquared > MIN_LENGTH_SQUARED ? v * inversesqrt(lengthSquared) : fallback;
}

// DESIGN §3's v: towards the eye, or +z under orthographic projection; a viewer on the surface sees it
// head-on (the normal).
vec3 toViewer(vec3 positionView, vec3 normalView) {
#if defined(VIEWER_AT_INFINITY)
    return vec3(0.0, 0.0, 1.0);
#elif defined(SPECIALIZED)
    return safeNormalize(-positionView, normalView);
#else
    return uOrthographic ? vec3(0.0, 0.0, 1.0) : safeNormalize(-positionView, normalView);
#endif
}

// x^SHININESS for x >= 0. A shininess compiled in as a whole number (SHININESS_INTEGER, 1..2047) is taken
// by squaring: the loop unrolls and folds to ⌊log₂ n⌋ squarings and a product per set bit (7 multiplies
// for 100), exact to float rounding, where pow is exp2(log2(x)·n): two polynomial approximations on
// llvmpipe.
float specularPower(float x) {
#ifdef SHININESS_INTEGER
    float result = 1.0;
    float square = x;
    for (int bit = 0; bit < 11; ++bit) {
        if (((SHININESS_INTEGER >> bit) & 1) != 0) result *= square;
        square *= square;
    }
    return result;
#else
    return pow(x, SHININESS);
#endif
}

// spec = max(v·r, 0)^α (Phong) or max(n·h, 0)^β (Blinn-Phong).
float specular(vec3 normalView, vec3 toViewerView, vec3 toLightView, float lDotN) {
#ifdef LIGHTING_BLINN_PHONG
    vec3 halfView = normalizeBounded(toViewerView + toLightView, normalView); // |v + l| <= 2
    return specularPower(max(dot(normalView, halfView), 0.0));
#else
    vec3 reflectedView = -toLightView + 2.0 * lDotN * normalView;
    return specularPower(max(dot(toViewerView, reflectedView), 0.0));
#endif
}

// factor·(k_d·I_d·max(l·n,0) + [l·n > 0]·k_s·I_s·spec): one light's direct term.
vec3 directTerm(Light light, vec3 toLightView, float factor, vec3 normalView, vec3 toViewerView) {
    float lDotN = dot(toLightView, normalView);
    float diffuse = max(lDotN, 0.0);
#ifdef SHADING_TOON
    diffuse = ceil(diffuse * TOON_BANDS) * TOON_BAND_WIDTH;
#endif
    vec3 color = light.diffuseProduct * diffuse;
#if HAS_SPECULAR
    float spec = lDotN > 0.0 ? specular(normalView, toViewerView, toLightView, lDotN) : 0.0;
#ifdef SHADING_TOON
    spec = spec > TOON_HIGHLIGHT ? 1.0 : 0.0;
#endif
    color += light.specularProduct * spec;
#endif
    return factor * color;
}

// A positional light's l and t; a light exactly on the surface lights it head-on: l falls back to the
// normal. `positional` numbers the specialized program's positional lights (points first, then spots).
// (A directional light's l is −directionView, made unit on the CPU.)
vec3 toLight(Light light, int positional, vec3 positionView, vec3 normalView, out float t) {
#if defined(INTERPOLATED_TO_LIGHT) && defined(FRAGMENT_STAGE)
    vec3 d = vToLightView[positional];
#else
    vec3 d = light.positionView - positionView;
#endif
    t = length(d); // unused, and so not computed, without HAS_ATTENUATION
    return safeNormalize(d, normalView);
}

// att = 1/(a + b·t + c·t²), the denominator floored so that a light on the surface with a = 0 stays finite.
float attenuation(Light light, float t) {
#if HAS_ATTENUATION
    vec3 k = light.attenuation;
    return 1.0 / max(k.x + k.y * t + k.z * t * t, MIN_ATTENUATION_DENOMINATOR);
#else
    return 1.0;
#endif
}

// spot = max(−l·d, 0)^e inside the cone, 0 outside; exponent 0 gives 1 even on a 90° cone's rim.
float spotFactor(Light light, vec3 toLightView) {
    float cosAngle = dot(-toLightView, light.directionView);
    if (cosAngle < light.cosCutoff) return 0.0;
    return light.exponent > 0.0 ? pow(max(cosAngle, 0.0), light.exponent) : 1.0;
}

vec3 shadeDirectional(Light light, vec3 positionView, vec3 normalView, vec3 toViewerView) {
    return directTerm(light, -light.directionView, 1.0, normalView, toViewerView);
}

vec3 shadePoint(Light light, int positional, vec3 positionView, vec3 normalView, vec3 toViewerView) {
    float t;
    vec3 toLightView = toLight(light, positional, positionView, normalView, t);
    return directTerm(light, toLightView, attenuation(light, t), normalView, toViewerView);
}

vec3 shadeSpot(Light light, int positional, vec3 positionView, vec3 normalView, vec3 toViewerView) {
    float t;
    vec3 toLightView = toLight(light, positional, positionView, normalView, t);
    float spot = spotFactor(light, toLightView);
    if (spot == 0.0) return vec3(0.0); // outside the cone: no term to evaluate
    return directTerm(light, toLightView, attenuation(light, t) * spot, normalView, toViewerView);
}

// Σ_lights [k_a·I_a + att·spot·(k_d·I_d·max(l·n,0) + [l·n > 0]·k_s·I_s·spec)], not clamped.
vec3 shade(vec3 positionView, vec3 normalView, vec3 toViewerView) {
    vec3 color = vec3(0.0);
#ifdef SPECIALIZED
#if HAS_AMBIENT
    color += AMBIENT_PRODUCT; // neither attenuated nor spot-limited
#endif
#if NUM_DIRECTIONAL > 0
    for (int i = 0; i < NUM_DIRECTIONAL; ++i)
        color += shadeDirectional(LIGHT_OF(uDirectionalLights, kDirectionalValues, i), positionView,
                                  normalView, toViewerView);
#endif
#if NUM_POINT > 0
    for (int i = 0; i < NUM_POINT; ++i)
        color += shadePoint(LIGHT_OF(uPointLights, kPointValues, i), i, positionView, normalView,
                            toViewerView);
#endif
#if NUM_SPOT > 0
    for (int i = 0; i < NUM_SPOT; ++i)
        color += shadeSpot(LIGHT_OF(uSpotLights, kSpotValues, i), NUM_POINT + i, positionView, normalView,
                           toViewerView);
#endif
#else
    for (int i = 0; i < uLightCount; ++i) {
        color += uLights[i].ambientProduct; // neither attenuated nor spot-limited
        int type = uLights[i].type;
        if (type == LIGHT_DIRECTIONAL)
            color += shadeDirectional(uLights[i], positionView, normalView, toViewerView);
        else if (type == LIGHT_POINT)
            color += shadePoint(uLights[i], i, positionView, normalView, toViewerView);
        else if (type == LIGHT_SPOT)
            color += shadeSpot(uLights[i], i, positionView, normalView, toViewerView);
    }
#endif
    return color;
}
