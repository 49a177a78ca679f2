// Vertex stage of exact shading (SHADING_EXACT): no mesh, only the proxy each object's rays are cast
// through, a screen-space rectangle that holds the object's projection (computed on the CPU from its
// bounding box; the whole viewport when the near plane cuts the box). lighting.glsl is prepended; this
// stage uses none of it. No attributes: the corners come from gl_VertexID (a 4-vertex triangle strip).

uniform vec4 uNdcRect; // x0, y0, x1, y1 in normalized device coordinates

void main() {
    vec2 corner = vec2(float(gl_VertexID & 1), float(gl_VertexID >> 1));
    // z = 0 lies inside both clip ranges ([−w, w] and [0, w]): the fragment stage writes the depth.
    gl_Position = vec4(mix(uNdcRect.xy, uNdcRect.zw, corner), 0.0, 1.0);
}
