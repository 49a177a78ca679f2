// Fragment stage of exact shading (SHADING_EXACT): each sphere or ellipsoid ray-cast through the pixel
// centre and lit at the hit point with the exact quadric normal by lighting.glsl's shade() — the analytic
// reference (src/exact/ray_cast.cpp, in double) drawn in real time: the same ray per pixel, the same stable
// quadratic, the same choice of root. lighting.glsl is prepended; its defines apply (VIEWER_AT_INFINITY or
// the uber program's uOrthographic also make the rays parallel). Writes gl_FragDepth from the hit point in
// the active depth convention, so exact objects hide each other as meshes do.

out vec4 fragColor;

uniform vec4 uViewport;       // x, y, width, height of the viewport in window pixels
uniform vec4 uNearRect;       // left, right, bottom, top of the view volume on the near plane
uniform vec2 uNearFar;        // near, far as positive distances (far 3e38 for an infinite far plane)
uniform mat3 uObjectFromView; // inverse of viewFromObject's 3×3: into the space where the object is the unit sphere
uniform vec3 uCenterView;     // the object's centre in view space (camera-relative, composed in double)
uniform mat3 uNormalViewFromObject; // cofactor matrix, rescaled: normals need renormalizing
uniform mat4 uClipFromView;
uniform float uDepthZeroToOne; // 1 under glClipControl's [0, 1] clip range (reversed-Z), else 0
uniform float uAlpha;          // coverage: 1, or the object's index + 1 for the error view's compare pass

#if defined(VIEWER_AT_INFINITY)
const bool kParallelRays = true;
#elif defined(SPECIALIZED)
const bool kParallelRays = false;
#else
#define kParallelRays uOrthographic
#endif

void main() {
    // PixelRays::ray: through the pixel centre on the near plane; orthographic rays start on z = 0.
    vec2 fraction = (gl_FragCoord.xy - uViewport.xy) / uViewport.zw;
    vec2 nearView = vec2(mix(uNearRect.x, uNearRect.y, fraction.x), mix(uNearRect.z, uNearRect.w, fraction.y));
    vec3 originView = kParallelRays ? vec3(nearView, 0.0) : vec3(0.0);
    vec3 directionView = kParallelRays ? vec3(0.0, 0.0, -1.0) : vec3(nearView, -uNearFar.x);

    // In the unit sphere's space. The discriminant is 1 − |o⊥|² (the ray's distance from the centre), not
    // b² − c, which cancels when |o| ≫ 1; the roots q and c/q never subtract nearly equal numbers
    // (Ray Tracing Gems, ch. 7).
    vec3 o = uObjectFromView * (originView - uCenterView);
    vec3 d = uObjectFromView * directionView;
    float dLength = length(d);
    vec3 dUnit = d / dLength;
    float b = dot(o, dUnit);
    vec3 perpendicular = o - b * dUnit;
    float disc = 1.0 - dot(perpendicular, perpendicular);
    if (!(disc >= 0.0)) discard;
    float root = sqrt(disc);
    float q = -(b + (b < 0.0 ? -root : root));
    float c = dot(o, o) - 1.0;
    float t0 = q, t1 = q != 0.0 ? c / q : 0.0;
    if (t0 > t1) {
        float swap = t0;
        t0 = t1;
        t1 = swap;
    }

    // The first root inside the clip volume: where the near plane cuts the object open, its far side
    // shows, lit with the outward normal as the reference does.
    float s = t0 / dLength;
    float side = -1.0;
    float zView = originView.z + s * directionView.z;
    if (!(zView <= -uNearFar.x && zView >= -uNearFar.y)) {
        s = t1 / dLength;
        side = 1.0;
        zView = originView.z + s * directionView.z;
        if (!(zView <= -uNearFar.x && zView >= -uNearFar.y)) discard;
    }
    vec3 pointObject = perpendicular + side * root * dUnit; // on the unit sphere: the object-space normal
    vec3 positionView = originView + s * directionView;
    vec3 normalView = safeNormalize(uNormalViewFromObject * pointObject, vec3(0.0, 0.0, 1.0));

    vec4 clip = uClipFromView * vec4(positionView, 1.0);
    if (!(clip.w > 0.0)) discard; // the clipper's w > 0, which a ray-cast fragment makes itself (camera.h)
    float depthNdc = clamp(clip.z / clip.w, -1.0, 1.0);
    gl_FragDepth = mix(0.5 * depthNdc + 0.5, depthNdc, uDepthZeroToOne);

    vec3 color = shade(positionView, normalView, toViewer(positionView, normalView));
    fragColor = vec4(clamp(color, 0.0, 1.0), uAlpha);
}
