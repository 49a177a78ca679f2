// The error view's picture (src/gl/views.cpp): each pixel's error (the compare pass's alpha, 1/255 units)
// through viridis, a perceptually uniform colour map that stays readable in grey and to colour-blind eyes,
// from 0 to uScale; uScale and above are its brightest yellow. Pixels neither render covers show the
// background. With uLegend the rectangle is the legend's bar instead: 0 at its bottom, uScale at its top.
// No defines.
uniform highp sampler2D uError;
uniform vec2 uOrigin;   // the viewport's lower left corner in window pixels
uniform float uScale;   // the error at the top of the colour map, in 1/255 units, > 0
uniform vec3 uBackground;
uniform bool uLegend;

in vec2 vUnit;
out vec4 color;

// Viridis (matplotlib's, by van der Walt and Smith) sampled at nine evenly spaced points, linearly
// interpolated between them: within 0.01 of the full table.
vec3 viridis(float t) {
    const vec3 stops[9] = vec3[9](vec3(0.267004, 0.004874, 0.329415), vec3(0.282623, 0.140926, 0.457517),
                                  vec3(0.253935, 0.265254, 0.529983), vec3(0.206756, 0.371758, 0.553117),
                                  vec3(0.163625, 0.471133, 0.558148), vec3(0.127568, 0.566949, 0.550556),
                                  vec3(0.134692, 0.658636, 0.517649), vec3(0.266941, 0.748751, 0.440573),
                                  vec3(0.993248, 0.906157, 0.143936));
    float x = clamp(t, 0.0, 1.0) * 8.0;
    int i = min(int(x), 7);
    return mix(stops[i], stops[i + 1], x - float(i));
}

void main() {
    if (uLegend) {
        color = vec4(viridis(vUnit.y), 1.0);
        return;
    }
    float error = texelFetch(uError, ivec2(gl_FragCoord.xy - uOrigin), 0).a;
    color = error < 0.0 ? vec4(uBackground, 0.0) : vec4(viridis(error / uScale), 1.0);
}
