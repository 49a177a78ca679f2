#include "app/demo_draw.h"

#include <algorithm>
#include <cmath>

#include "shadelab/overlay.h"

namespace shadelab::app {

void drawDemo(gl::Renderer& renderer, const DemoState& state, int width, int height, int x) {
    const Scene scene = state.drawn();
    renderer.render(scene, width, height, x);
    const auto probe = state.probe();
    if (!probe) return;
    // The vectors are as long as 0.6 of the object's largest semi-axis: visible, and inside the picture.
    const SceneObject& object = scene.objects[probe->point.object];
    const double length =
        0.6 * object.radius *
        std::max({std::abs(object.scale.x), std::abs(object.scale.y), std::abs(object.scale.z)});
    renderer.drawLinesOver(scene, probeLines(*probe, length), width, height, x);
}

} // namespace shadelab::app
