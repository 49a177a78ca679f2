// Fragment stage of every surface program. lighting.glsl is prepended.
// Defines it responds to: SHADING_FLAT, SHADING_GOURAUD (colour from the vertex stage) or SHADING_PHONG,
// SHADING_TOON (lighting per fragment with the interpolated, renormalized normal).
// NDC_VIEW: vCameraClip, the camera's clip coordinates (linear on the object's triangle, as interpolated),
// and the clipper's test made per fragment: only what lies inside the camera's view volume is drawn.
// TWO_SIDED: an open surface (DESIGN §3 "Open surfaces"): a back face (gl_FrontFacing false; the draw sets
// glFrontFace so that front means the outside faces the eye) is lit with its normal turned over — the
// per-fragment normal negated, or flat's and Gouraud's colour lit so in the vertex stage.
// Alpha is coverage: 1 on objects; the background is cleared to alpha 0. OBJECT_ID_ALPHA: alpha is uAlpha
// (a mesh drawn as the exact answer of the error view's compare pass writes its object's index + 1).

out vec4 fragColor;

#if defined(SHADING_FLAT)
flat in vec3 vColor;
#if defined(TWO_SIDED) && !defined(FLAT_GEOMETRY_SHADER)
flat in vec3 vColorBack;
#endif
#elif defined(SHADING_GOURAUD)
in vec3 vColor;
#ifdef TWO_SIDED
in vec3 vColorBack;
#endif
#else
in vec3 vPositionView;
in vec3 vNormalView;
#endif

#ifdef NDC_VIEW
in vec4 vCameraClip;
#endif

#ifdef OBJECT_ID_ALPHA
uniform float uAlpha;
#define COVERAGE uAlpha
#else
#define COVERAGE 1.0
#endif

void main() {
#ifdef NDC_VIEW
    if (!(vCameraClip.w > 0.0) || any(greaterThan(abs(vCameraClip.xyz), vec3(vCameraClip.w)))) discard;
#endif
#if defined(SHADING_FLAT) || defined(SHADING_GOURAUD)
    vec3 color = vColor;
#if defined(TWO_SIDED) && !defined(FLAT_GEOMETRY_SHADER) // the geometry stage turns the normal itself
    if (!gl_FrontFacing) color = vColorBack;
#endif
    fragColor = vec4(color, COVERAGE);
#else
    vec3 normalView = normalizeBounded(vNormalView, vec3(0.0, 0.0, 1.0));
#ifdef TWO_SIDED
    if (!gl_FrontFacing) normalView = -normalView;
#endif
    vec3 color = shade(vPositionView, normalView, toViewer(vPositionView, normalView));
    fragColor = vec4(clamp(color, 0.0, 1.0), COVERAGE);
#endif
}
