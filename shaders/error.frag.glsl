// The error view's compare pass (src/gl/views.cpp): per pixel |mode − exact| from two float renders of the
// same scene, and whether the pixel is interior as `shadelab report` counts it
// (src/app/report/report_error.cpp, measureError with interiorMask(…, 2)): the 5×5 square around it lies
// inside the image, is covered by the same object in the exact render (its alpha holds object index + 1)
// and is covered in the mode's render.
// No defines. Output, in 1/255 units: r = mean of |ΔR|, |ΔG|, |ΔB| on interior pixels (else 0); g = 1 on
// interior pixels (else 0); b = largest of them on interior pixels (else 0); a = largest of them wherever
// either render covers the pixel, −1 where neither does (the heatmap shows it; the background stays).
uniform highp sampler2D uMode;
uniform highp sampler2D uExact;

out vec4 errorOut;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 size = textureSize(uExact, 0);
    vec4 mode = texelFetch(uMode, p, 0);
    vec4 exact = texelFetch(uExact, p, 0);
    vec3 delta = abs(mode.rgb - exact.rgb) * 255.0;
    float largest = max(max(delta.r, delta.g), delta.b);
    bool covered = mode.a > 0.5 || exact.a > 0.5;
    bool interior = exact.a > 0.5 && all(greaterThanEqual(p, ivec2(2))) && all(lessThan(p, size - 2));
    if (interior) {
        for (int dy = -2; dy <= 2; ++dy) {
            for (int dx = -2; dx <= 2; ++dx) {
                ivec2 q = p + ivec2(dx, dy);
                interior = interior && texelFetch(uExact, q, 0).a == exact.a && texelFetch(uMode, q, 0).a > 0.5;
            }
        }
    }
    float meanOfChannels = (delta.r + delta.g + delta.b) / 3.0;
    errorOut = vec4(interior ? meanOfChannels : 0.0, interior ? 1.0 : 0.0, interior ? largest : 0.0,
                    covered ? largest : -1.0);
}
