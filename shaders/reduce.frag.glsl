// One step of the error view's reduction (src/gl/views.cpp): each output texel sums r and g and takes the
// largest b over a 4×4 block of the input (the part of it inside the input), so that after a few steps one
// texel holds the interior's error sum, its pixel count and its largest error. No defines.
uniform highp sampler2D uInput;

out vec4 reduced;

void main() {
    ivec2 size = textureSize(uInput, 0);
    ivec2 first = ivec2(gl_FragCoord.xy) * 4;
    vec4 sum = vec4(0.0);
    for (int dy = 0; dy < 4; ++dy) {
        for (int dx = 0; dx < 4; ++dx) {
            ivec2 q = first + ivec2(dx, dy);
            if (q.x >= size.x || q.y >= size.y) continue;
            vec4 v = texelFetch(uInput, q, 0);
            sum.rg += v.rg;
            sum.b = max(sum.b, v.b);
        }
    }
    reduced = sum;
}
