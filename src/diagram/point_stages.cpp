#include "shadelab/diagram/point_stages.h"

#include <string>

#include "shadelab/errors.h"

namespace shadelab {

PointStages tracePoint(const Scene& scene, std::size_t object, const glm::dvec3& pointObject) {
    if (object >= scene.objects.size())
        throw InputError("the traced point's object " + std::to_string(object + 1) +
                         " is not in the scene (" + std::to_string(scene.objects.size()) + " objects)");
    const SceneView view = sceneView(scene);
    PointStages stages;
    stages.object = pointObject;
    stages.world = glm::dvec3(worldFromObject(scene.objects[object]) * glm::dvec4(pointObject, 1.0));
    stages.camera = glm::dvec3(view.viewFromWorld * glm::dvec4(stages.world, 1.0));
    stages.clip = view.clipFromView * glm::dvec4(stages.camera, 1.0);
    stages.behindEye = !(stages.clip.w > 0);
    if (stages.behindEye) return stages;
    stages.ndc = glm::dvec3(stages.clip) / stages.clip.w;
    const bool zeroToOne = view.depth != DepthMode::Standard; // glClipControl's [0, 1] clip range
    const double depth = zeroToOne ? stages.ndc.z : 0.5 * stages.ndc.z + 0.5;
    // The viewport transform: x right, y down from the top row (NDC's y is up).
    stages.window = {0.5 * (stages.ndc.x + 1.0) * scene.width, 0.5 * (1.0 - stages.ndc.y) * scene.height,
                     depth};
    const auto within = [](double v, double low) { return v >= low && v <= 1.0; };
    stages.insideVolume = within(stages.ndc.x, -1.0) && within(stages.ndc.y, -1.0) &&
                          within(stages.ndc.z, zeroToOne ? 0.0 : -1.0);
    return stages;
}

} // namespace shadelab
