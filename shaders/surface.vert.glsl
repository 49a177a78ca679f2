// Vertex stage of every surface program. lighting.glsl is prepended.
// Defines it responds to (exactly one of):
//   SHADING_FLAT     light once per triangle at its centroid with its face normal (attribute 2: centroid)
//   SHADING_GOURAUD  light per vertex with the vertex normal, clamp, interpolate the colour
//   SHADING_PHONG, SHADING_TOON  pass view-space position and normal on for per-fragment lighting
//   NEEDS_NORMAL     (set in lighting.glsl) 0 when only ambient light reaches the scene: no normal attribute
//   FLAT_GEOMETRY_SHADER  with SHADING_FLAT: shared vertices; surface.geom.glsl derives each triangle's
//                    centroid and face normal and lights it once (no centroid or normal attribute)
//   NDC_VIEW         uClipFromObject is the observer's view of the camera's NDC space; the camera's own clip
//                    coordinates go to the fragment stage, which discards what the clipper would remove
//   TWO_SIDED        an open surface (DESIGN §3 "Open surfaces"): flat and Gouraud also light each vertex
//                    with the normal turned over (vColorBack), which the fragment stage takes for a back face
#if defined(FLAT_GEOMETRY_SHADER) && NEEDS_NORMAL
#undef NEEDS_NORMAL
#define NEEDS_NORMAL 0
#endif

layout(location = 0) in vec3 aPositionObject;
#if NEEDS_NORMAL
layout(location = 1) in vec3 aNormalObject; // flat: the face normal
#else
const vec3 aNormalObject = vec3(0.0, 0.0, 1.0); // only ambient light: the normal is never used
#endif
#if defined(SHADING_FLAT) && !defined(FLAT_GEOMETRY_SHADER)
layout(location = 2) in vec3 aCentroidObject;
#endif

uniform mat4 uClipFromObject;       // composed in double on the CPU
uniform mat4 uViewFromObject;       // camera-relative: no large world coordinates reach float
uniform mat3 uNormalViewFromObject; // cofactor of the upper 3×3: normals need renormalizing
#ifdef NDC_VIEW
uniform mat4 uCameraClipFromObject; // M_proj·M_cam·M of the camera (uClipFromObject is the observer's)
out vec4 vCameraClip;
#endif

#if defined(FLAT_GEOMETRY_SHADER)
out vec3 vPositionView;
#elif defined(SHADING_FLAT)
flat out vec3 vColor;
#ifdef TWO_SIDED
flat out vec3 vColorBack;
#endif
#elif defined(SHADING_GOURAUD)
out vec3 vColor;
#ifdef TWO_SIDED
out vec3 vColorBack;
#endif
#else
out vec3 vPositionView;
out vec3 vNormalView;
#endif

vec3 lightAt(vec3 pointObject, vec3 normalObject) {
    vec3 positionView = (uViewFromObject * vec4(pointObject, 1.0)).xyz;
    vec3 normalView = safeNormalize(uNormalViewFromObject * normalObject, vec3(0.0, 0.0, 1.0));
    return clamp(shade(positionView, normalView, toViewer(positionView, normalView)), 0.0, 1.0);
}

void main() {
    gl_Position = uClipFromObject * vec4(aPositionObject, 1.0);
#ifdef NDC_VIEW
    vCameraClip = uCameraClipFromObject * vec4(aPositionObject, 1.0);
#endif
#if defined(FLAT_GEOMETRY_SHADER)
    vPositionView = (uViewFromObject * vec4(aPositionObject, 1.0)).xyz;
#elif defined(SHADING_FLAT)
    vColor = lightAt(aCentroidObject, aNormalObject);
#ifdef TWO_SIDED
    vColorBack = lightAt(aCentroidObject, -aNormalObject);
#endif
#elif defined(SHADING_GOURAUD)
    vColor = lightAt(aPositionObject, aNormalObject);
#ifdef TWO_SIDED
    vColorBack = lightAt(aPositionObject, -aNormalObject); // OpenGL's two-sided lighting did the same
#endif
#else
    vec3 positionView = (uViewFromObject * vec4(aPositionObject, 1.0)).xyz;
    vPositionView = positionView;
    vNormalView = uNormalViewFromObject * aNormalObject;
#ifdef INTERPOLATED_TO_LIGHT // lighting.glsl: p_light − p per positional light, points first
#if NUM_POINT > 0
    for (int i = 0; i < NUM_POINT; ++i) vToLightView[i] = uPointLights[i].positionView - positionView;
#endif
#if NUM_SPOT > 0
    for (int i = 0; i < NUM_SPOT; ++i)
        vToLightView[NUM_POINT + i] = uSpotLights[i].positionView - positionView;
#endif
#endif
#endif
}
