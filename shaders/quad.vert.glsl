// Vertex stage of the views' screen-space passes (src/gl/views.cpp): a rectangle from gl_VertexID (a
// 4-vertex triangle strip, no attributes). No defines; nothing prepended but the version.
uniform vec4 uNdcRect; // x0, y0, x1, y1 in normalized device coordinates

out vec2 vUnit; // 0..1 across the rectangle, (0, 0) at its lower left

void main() {
    vUnit = vec2(float(gl_VertexID & 1), float(gl_VertexID >> 1));
    gl_Position = vec4(mix(uNdcRect.xy, uNdcRect.zw, vUnit), 0.0, 1.0);
}
