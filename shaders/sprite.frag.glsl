// Labels, legends and plots drawn into the picture (src/gl/views.cpp): an RGBA image made on the CPU,
// one texel per pixel, blended over what is there by its alpha. No defines.
uniform highp sampler2D uImage;
uniform vec2 uOrigin; // the image's lower left corner in window pixels

out vec4 color;

void main() {
    ivec2 size = textureSize(uImage, 0);
    ivec2 p = ivec2(gl_FragCoord.xy - uOrigin);
    color = texelFetch(uImage, ivec2(p.x, size.y - 1 - p.y), 0); // the image's rows are top first
}
