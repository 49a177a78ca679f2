// The lighting equations of DESIGN §3: the GLSL mirror of src/lighting.cpp (change both together).
// Prepended to both stages of every program. All vectors are in view space; the viewer is at the origin.
// Defines it responds to:
//   MAX_LIGHTS            size of the light array (always defined by the loader)
//   LIGHTING_BLINN_PHONG  Blinn-Phong specular max(n·h,0)^β; otherwise Phong max(v·r,0)^α
//   SHADING_TOON          diffuse quantized into uToonBands bands, highlight thresholded at TOON_HIGHLIGHT

const int LIGHT_AMBIENT = 0;
const int LIGHT_DIRECTIONAL = 1;
const int LIGHT_POINT = 2;
const int LIGHT_SPOT = 3;

struct Light {
    int type;
    vec3 ambient;
    vec3 diffuse;
    vec3 specular;
    vec3 positionView;
    vec3 directionView; // unit; the direction the light travels
    float cosCutoff;
    float exponent;
    vec3 attenuation;   // a, b, c of 1/(a + b·t + c·t²)
};

uniform Light uLights[MAX_LIGHTS];
uniform int uLightCount;
uniform vec3 uMaterialAmbient;
uniform vec3 uMaterialDiffuse;
uniform vec3 uMaterialSpecular;
uniform float uShininess;    // >= 1: pow(0, 0) is undefined in GLSL
uniform bool uOrthographic;  // parallel projection: the viewer direction is +z everywhere
uniform float uToonBands;    // SHADING_TOON only

// normalize(v), or the fallback where v is too short to normalize (DESIGN §3 guards). Scaling by the
// largest component first keeps dot(v, v) from overflowing or underflowing float.
vec3 safeNormalize(vec3 v, vec3 fallback) {
    float largest = max(max(abs(v.x), abs(v.y)), abs(v.z));
    if (!(largest > 1e-30)) return fallback;
    vec3 scaled = v / largest;
    return scaled * inversesqrt(dot(scaled, scaled));
}

vec3 toViewer(vec3 positionView, vec3 normalView) {
    return uOrthographic ? vec3(0.0, 0.0, 1.0) : safeNormalize(-positionView, normalView);
}

float specularTerm(vec3 normalView, vec3 toViewerView, vec3 toLightView, float lDotN) {
#ifdef LIGHTING_BLINN_PHONG
    vec3 halfView = safeNormalize(toViewerView + toLightView, normalView);
    return pow(max(dot(normalView, halfView), 0.0), uShininess);
#else
    vec3 reflectedView = -toLightView + 2.0 * lDotN * normalView;
    return pow(max(dot(toViewerView, reflectedView), 0.0), uShininess);
#endif
}

// Σ_lights [k_a·I_a + att·spot·(k_d·I_d·max(l·n,0) + [l·n > 0]·k_s·I_s·spec)], not clamped.
vec3 shade(vec3 positionView, vec3 normalView, vec3 toViewerView) {
    vec3 color = vec3(0.0);
    for (int i = 0; i < uLightCount; ++i) {
        color += uMaterialAmbient * uLights[i].ambient; // neither attenuated nor spot-limited
        int type = uLights[i].type;
        if (type == LIGHT_AMBIENT) continue;

        vec3 toLightView = -uLights[i].directionView;
        float factor = 1.0;
        if (type != LIGHT_DIRECTIONAL) {
            vec3 d = uLights[i].positionView - positionView;
            float t = length(d);
            // A light exactly on the surface lights it head-on.
            toLightView = safeNormalize(d, normalView);
            vec3 k = uLights[i].attenuation;
            factor = 1.0 / max(k.x + k.y * t + k.z * t * t, 1e-12);
        }
        if (type == LIGHT_SPOT) {
            float cosAngle = dot(-toLightView, uLights[i].directionView);
            float e = uLights[i].exponent;
            factor *= cosAngle < uLights[i].cosCutoff ? 0.0 : (e > 0.0 ? pow(max(cosAngle, 0.0), e) : 1.0);
        }
        float lDotN = dot(toLightView, normalView);
        float diffuse = max(lDotN, 0.0);
        float spec = lDotN > 0.0 ? specularTerm(normalView, toViewerView, toLightView, lDotN) : 0.0;
#ifdef SHADING_TOON
        diffuse = ceil(diffuse * uToonBands) / uToonBands;
        spec = spec > TOON_HIGHLIGHT ? 1.0 : 0.0;
#endif
        color += factor * (uMaterialDiffuse * uLights[i].diffuse * diffuse +
                           uMaterialSpecular * uLights[i].specular * spec);
    }
    return color;
}
