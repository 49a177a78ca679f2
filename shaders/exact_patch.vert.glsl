// Vertex stage of the teapot's exact shading (SHADING_EXACT with EXACT_PATCHES): the proxy each pixel's ray
// is refined from, a fine teapot mesh pushed out to cover the surface (src/gl/scene_draw.cpp exactProxy)
// carrying each vertex's (patch, u, v) (geometry/teapot.h patchUv). lighting.glsl is prepended; this stage
// uses none of it.

layout(location = 0) in vec3 aPositionObject;
layout(location = 2) in vec3 aPatchUv; // patch index, u, v

uniform mat4 uClipFromObject;

flat out int vPatch;
out vec2 vUv;

void main() {
    vPatch = int(aPatchUv.x + 0.5);
    vUv = aPatchUv.yz;
    gl_Position = uClipFromObject * vec4(aPositionObject, 1.0);
}
