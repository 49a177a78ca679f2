// Geometry stage of flat shading with shared vertices (FLAT_GEOMETRY_SHADER). lighting.glsl is prepended.
// Each triangle's centroid and face normal are derived from its three view-space positions and it is lit
// once there (DESIGN §3), so the vertex buffer needs no per-face copies. The duplicated-vertex layout
// (FlatVertex) gives the same picture; `shadelab bench` measures which costs less.
// TWO_SIDED (DESIGN §3 "Open surfaces"): the face normal is turned towards the eye before lighting — from
// the centroid and the eye, which is what gl_FrontFacing decides for the other flat layout.

layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

in vec3 vPositionView[];
flat out vec3 vColor;

uniform float uHandedness; // −1 for a mirrored object: its counter-clockwise faces turn clockwise

void main() {
    vec3 centroidView = (vPositionView[0] + vPositionView[1] + vPositionView[2]) / 3.0;
    vec3 edgeCross = cross(vPositionView[1] - vPositionView[0], vPositionView[2] - vPositionView[0]);
    vec3 normalView = safeNormalize(uHandedness * edgeCross, vec3(0.0, 0.0, 1.0));
#ifdef TWO_SIDED
    if (dot(normalView, toViewer(centroidView, normalView)) < 0.0) normalView = -normalView;
#endif
    vec3 color = clamp(shade(centroidView, normalView, toViewer(centroidView, normalView)), 0.0, 1.0);
    for (int i = 0; i < 3; ++i) {
        gl_Position = gl_in[i].gl_Position;
        vColor = color;
        EmitVertex();
    }
    EndPrimitive();
}
