// Vertex stage of the overlay's lines (mesh edges and normals, the probe's vectors). No defines; nothing
// prepended but the version. Positions are in whatever space uClipFromSpace maps from: object space for an
// object's edges and normals, view space for the probe.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aColor;

uniform mat4 uClipFromSpace; // composed in double on the CPU

out vec3 vColor;

void main() {
    gl_Position = uClipFromSpace * vec4(aPosition, 1.0);
    vColor = aColor;
}
