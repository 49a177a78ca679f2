// Fragment stage of the overlay's lines: the vertex colour, opaque unless uTranslucency says otherwise
// (the outside view's near and far faces, drawn blended). No defines.
in vec3 vColor;
out vec4 fragColor;

uniform float uTranslucency; // 0 (the default value of a uniform never set): opaque

void main() {
    fragColor = vec4(vColor, 1.0 - uTranslucency);
}
