// Fragment stage of every surface program. lighting.glsl is prepended.
// Defines it responds to: SHADING_FLAT, SHADING_GOURAUD (colour from the vertex stage) or SHADING_PHONG,
// SHADING_TOON (lighting per fragment with the interpolated, renormalized normal).
// NDC_VIEW: vCameraClip, the camera's clip coordinates (linear on the object's triangle, as interpolated),
// and the clipper's test made per fragment: only what lies inside the camera's view volume is drawn.
// Alpha is coverage: 1 on objects; the background is cleared to alpha 0.

out vec4 fragColor;

#if defined(SHADING_FLAT)
flat in vec3 vColor;
#elif defined(SHADING_GOURAUD)
in vec3 vColor;
#else
in vec3 vPositionView;
in vec3 vNormalView;
#endif

#ifdef NDC_VIEW
in vec4 vCameraClip;
#endif

void main() {
#ifdef NDC_VIEW
    if (!(vCameraClip.w > 0.0) || any(greaterThan(abs(vCameraClip.xyz), vec3(vCameraClip.w)))) discard;
#endif
#if defined(SHADING_FLAT) || defined(SHADING_GOURAUD)
    fragColor = vec4(vColor, 1.0);
#else
    vec3 normalView = normalizeBounded(vNormalView, vec3(0.0, 0.0, 1.0));
    vec3 color = shade(vPositionView, normalView, toViewer(vPositionView, normalView));
    fragColor = vec4(clamp(color, 0.0, 1.0), 1.0);
#endif
}
