// Fragment stage of the overlay's lines: the vertex colour, opaque. No defines.
in vec3 vColor;
out vec4 fragColor;

void main() {
    fragColor = vec4(vColor, 1.0);
}
