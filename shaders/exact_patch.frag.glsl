// Fragment stage of the teapot's exact shading (SHADING_EXACT with EXACT_PATCHES): the ray through the pixel
// centre (as shaders/exact.frag.glsl casts it) meets the Bézier patch of the proxy fragment where Newton's
// iteration, started from the fragment's interpolated (u, v), takes it: the ray is written as two planes
// N₁·x + d₁ = 0, N₂·x + d₂ = 0 (Kajiya; Martin et al., "Practical ray tracing of trimmed NURBS"), so the
// unknowns are (u, v) alone. A fragment whose iteration does not converge inside its patch's domain (less a
// small margin across its borders) is discarded: a neighbouring patch's fragment finds that hit. Lit at the
// hit with the patch's analytic normal (geometry/teapot.h patchNormal, the cusp rule included), turned
// towards the viewer when it faces away from the ray (DESIGN §3 "Open surfaces": the teapot is open), and
// gl_FragDepth written from the hit, so the nearest hit of all the proxy's fragments wins.
// Only what GL 3.3, GLES 3.0 and WebGL 2 all have: a std140 uniform block of 512 vec4 (8 KiB; each API
// guarantees 16 KiB), no geometry stage, no storage buffer.
// Defines it responds to: lighting.glsl's; VIEWER_AT_INFINITY or uOrthographic make the rays parallel.

out vec4 fragColor;

layout(std140) uniform TeapotPatches {
    // Patch p's P[4i + j] at 16p + 4i + j (xyz). The w of its first four: how far a hit may lie beyond its
    // borders u = 0, u = 1, v = 0, v = 1 in (u, v) (src/gl/scene_draw.cpp borderMargins).
    vec4 uControlPointsObject[512];
};

uniform vec4 uViewport;       // x, y, width, height of the viewport in window pixels
uniform vec4 uNearRect;       // left, right, bottom, top of the view volume on the near plane
uniform vec2 uNearFar;        // near, far as positive distances (far 3e38 for an infinite far plane)
uniform mat3 uObjectFromView; // inverse of viewFromObject's 3×3
uniform vec3 uCenterView;     // the object's origin in view space (camera-relative, composed in double)
uniform mat3 uNormalViewFromObject; // cofactor matrix, rescaled: normals need renormalizing
uniform mat4 uClipFromView;
uniform float uDepthZeroToOne; // 1 under glClipControl's [0, 1] clip range (reversed-Z), else 0
uniform float uAlpha;          // coverage: 1, or the object's index + 1 for the error view's compare pass

flat in int vPatch;
in vec2 vUv;

#if defined(VIEWER_AT_INFINITY)
const bool kParallelRays = true;
#elif defined(SPECIALIZED)
const bool kParallelRays = false;
#else
#define kParallelRays uOrthographic
#endif

const int kNewtonSteps = 10;
const int kPolishSteps = 2;
// |residual| in object units (the teapot is 2 high): well under a pixel at any size shadelab draws, and
// above float's rounding of a point on the patch (~1e-6 where the ray starts 10 units away).
const float kToleranceObject = 2e-5;

// The cubic Bernstein polynomials at t and their derivatives.
void bernstein(float t, out float b[4], out float db[4]) {
    float s = 1.0 - t;
    b[0] = s * s * s;
    b[1] = 3.0 * t * s * s;
    b[2] = 3.0 * t * t * s;
    b[3] = t * t * t;
    db[0] = -3.0 * s * s;
    db[1] = 3.0 * s * s - 6.0 * t * s;
    db[2] = 6.0 * t * s - 3.0 * t * t;
    db[3] = 3.0 * t * t;
}

// P(u, v) = Σᵢ Σⱼ Bᵢ(u) Bⱼ(v) P[4i + j] and its partial derivatives (geometry/teapot.h evaluatePatch).
void evaluatePatch(int patchIndex, vec2 uv, out vec3 p, out vec3 du, out vec3 dv) {
    float bu[4], dbu[4], bv[4], dbv[4];
    bernstein(uv.x, bu, dbu);
    bernstein(uv.y, bv, dbv);
    p = vec3(0.0);
    du = vec3(0.0);
    dv = vec3(0.0);
    for (int i = 0; i < 4; ++i) {
        vec3 row = vec3(0.0), rowDv = vec3(0.0);
        for (int j = 0; j < 4; ++j) {
            vec3 c = uControlPointsObject[16 * patchIndex + 4 * i + j].xyz;
            row += bv[j] * c;
            rowDv += dbv[j] * c;
        }
        p += bu[i] * row;
        du += dbu[i] * row;
        dv += bu[i] * rowDv;
    }
}

void main() {
    // PixelRays::ray, as shaders/exact.frag.glsl.
    vec2 fraction = (gl_FragCoord.xy - uViewport.xy) / uViewport.zw;
    vec2 nearView = vec2(mix(uNearRect.x, uNearRect.y, fraction.x), mix(uNearRect.z, uNearRect.w, fraction.y));
    vec3 originView = kParallelRays ? vec3(nearView, 0.0) : vec3(0.0);
    vec3 directionView = kParallelRays ? vec3(0.0, 0.0, -1.0) : vec3(nearView, -uNearFar.x);

    vec3 o = uObjectFromView * (originView - uCenterView);
    vec3 d = uObjectFromView * directionView;
    // Two unit planes through the ray, perpendicular to each other.
    vec3 a = abs(d.x) > abs(d.y) && abs(d.x) > abs(d.z) ? vec3(d.y, -d.x, 0.0) : vec3(0.0, d.z, -d.y);
    vec3 n1 = normalize(a);
    vec3 n2 = normalize(cross(n1, d));
    vec2 offset = -vec2(dot(n1, o), dot(n2, o));

    vec2 uv = vUv;
    vec3 p, du, dv;
    bool converged = false;
    int polished = 0;
    for (int iteration = 0; iteration <= kNewtonSteps; ++iteration) {
        evaluatePatch(vPatch, uv, p, du, dv);
        vec2 residual = vec2(dot(n1, p), dot(n2, p)) + offset;
        converged = max(abs(residual.x), abs(residual.y)) < kToleranceObject;
        // A few steps more once within the tolerance: where two surfaces cross (the spout into the body) the
        // nearer is decided by depths that the tolerance alone leaves uncertain.
        if (converged && polished++ == kPolishSteps) break;
        if (iteration == kNewtonSteps) break;
        mat2 jacobian = mat2(dot(n1, du), dot(n2, du), dot(n1, dv), dot(n2, dv)); // columns ∂/∂u, ∂/∂v
        float det = determinant(jacobian);
        if (!(abs(det) > 1e-20)) break;
        // Kept near the patch: a step that leaves it far behind has found no hit of this patch.
        uv = clamp(uv - inverse(jacobian) * residual, -0.5, 1.5);
    }
    vec4 margin = vec4(uControlPointsObject[16 * vPatch].w, uControlPointsObject[16 * vPatch + 1].w,
                       uControlPointsObject[16 * vPatch + 2].w, uControlPointsObject[16 * vPatch + 3].w);
    // Near a cusp a small step in space is a large one in the other parameter (the angle about the cusp):
    // there the seams beside it let the hit lie farther across, the extrapolated patch still the next one's
    // surface to within |u|·margin².
    const float kCusp = 0.1; // borderMargins gives a collapsed border more than this
    if ((margin.x > kCusp && uv.x < 0.05) || (margin.y > kCusp && uv.x > 0.95)) margin.zw = vec2(0.5);
    if ((margin.z > kCusp && uv.y < 0.05) || (margin.w > kCusp && uv.y > 0.95)) margin.xy = vec2(0.5);
    if (!converged || uv.x < -margin.x || uv.x > 1.0 + margin.y || uv.y < -margin.z || uv.y > 1.0 + margin.w)
        discard;

    float s = dot(p - o, d) / dot(d, d);
    vec3 positionView = originView + s * directionView;
    if (!(s > 0.0) || !(positionView.z <= -uNearFar.x && positionView.z >= -uNearFar.y)) discard;

    // normalize(∂P/∂v × ∂P/∂u); at a cusp (the cross product vanishes) +y above the middle, −y below.
    // At a cusp one derivative vanishes (a border collapsed to a point: the lid's apex, the bottom's
    // centre) and in float comes out as rounding noise in any direction, so the test is relative: within
    // 1e-4 of the other (these caps' normals are that close to ±y there).
    vec3 crossObject = cross(dv, du);
    float du2 = dot(du, du), dv2 = dot(dv, dv);
    bool cusp = !(min(du2, dv2) > 1e-8 * max(du2, dv2));
    vec3 normalObject = cusp ? vec3(0.0, p.y > 0.0 ? 1.0 : -1.0, 0.0) : crossObject;
    vec3 normalView = safeNormalize(uNormalViewFromObject * normalObject, vec3(0.0, 0.0, 1.0));
    if (dot(normalView, directionView) > 0.0) normalView = -normalView;

    vec4 clip = uClipFromView * vec4(positionView, 1.0);
    if (!(clip.w > 0.0)) discard;
    float depthNdc = clamp(clip.z / clip.w, -1.0, 1.0);
    gl_FragDepth = mix(0.5 * depthNdc + 0.5, depthNdc, uDepthZeroToOne);

    vec3 color = shade(positionView, normalView, toViewer(positionView, normalView));
    fragColor = vec4(clamp(color, 0.0, 1.0), uAlpha);
}
