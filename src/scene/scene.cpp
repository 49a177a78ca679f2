// The scene's vocabularies, defaults and derived matrices (DESIGN §4). Reading a scene file is
// scene_json.cpp (text → tree) and scene_parse.cpp (tree → Scene), its ranges scene_check.cpp, writing it
// scene_write.cpp.
#include "shadelab/scene/scene.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/scene_internal.h"
#include "shadelab/io/text.h"
#include "shadelab/scene/model.h"
#include "shadelab/vocabulary.h"

namespace shadelab {

using namespace detail;

std::string_view toString(DepthMode mode) {
    switch (mode) {
    case DepthMode::Standard:
        return "standard";
    case DepthMode::Reversed:
        return "reversed";
    case DepthMode::ReversedInfinite:
        return "reversed-infinite";
    }
    return "unknown";
}

std::string_view toString(Overlay overlay) {
    switch (overlay) {
    case Overlay::None:
        return "none";
    case Overlay::Wireframe:
        return "wireframe";
    case Overlay::Normals:
        return "normals";
    case Overlay::Lights:
        return "lights";
    }
    return "unknown";
}

std::string_view toString(Shape shape) {
    switch (shape) {
    case Shape::Sphere:
        return "sphere";
    case Shape::Teapot:
        return "teapot";
    case Shape::Mesh:
        return "mesh";
    }
    return "unknown";
}

bool isClosed(const SceneObject& object) {
    return object.shape == Shape::Sphere || (object.shape == Shape::Mesh && object.closed);
}

std::string_view toString(ProjectionType type) {
    switch (type) {
    case ProjectionType::Perspective:
        return "perspective";
    case ProjectionType::Frustum:
        return "frustum";
    case ProjectionType::Orthographic:
        return "orthographic";
    }
    return "unknown";
}

Light Scene::defaultLight() {
    Light light;
    light.type = LightType::Point;
    light.position = {3, 3, 5};
    light.ambient = glm::dvec3(0.1);
    light.diffuse = glm::dvec3(1);
    light.specular = glm::dvec3(1);
    light.attenuation = {1, 0, 0};
    return light;
}

SceneView sceneView(const Scene& scene) {
    checkSceneSize(scene);
    checkProjection(scene.projection);
    SceneView view;
    try {
        view.viewFromWorld = viewFromWorld(cameraFrame(scene.eye, scene.target, scene.up));
    } catch (const InputError& e) {
        failWithin("camera", e);
    }
    const Projection& p = scene.projection;
    view.orthographic = p.type == ProjectionType::Orthographic;
    try {
        if (p.type == ProjectionType::Perspective) {
            double aspect = static_cast<double>(scene.width) / scene.height;
            view.volume = viewVolumeFromFovy(p.fovyDeg, aspect, p.near, p.far);
        } else {
            view.volume = ViewVolume{p.left, p.right, p.bottom, p.top, p.near, p.far};
        }
        validateViewVolume(view.volume);
    } catch (const InputError& e) {
        failWithin("projection", e);
    }
    view.depth = scene.depth;
    // Valid planes can still be too close together or too large for double (left 0, right 1e-320;
    // near 1e200): the matrices must come out finite, or the projection is an input error.
    auto finiteMatrix = [](const glm::dmat4& m) {
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                if (!std::isfinite(m[c][r])) return false;
        return true;
    };
    if (scene.depth == DepthMode::Standard)
        view.clipFromView =
            view.orthographic ? orthographicClipFromView(view.volume) : perspectiveClipFromView(view.volume);
    else
        view.clipFromView =
            view.orthographic
                ? reversedOrthographicClipFromView(view.volume)
                : reversedPerspectiveClipFromView(view.volume, scene.depth == DepthMode::ReversedInfinite);
    // The perspective matrix before DESIGN §2's multiplication by −1, on purpose (camera.h).
    if (leavesOutTheMinusOne(scene)) view.clipFromView = -view.clipFromView;
    if (!finiteMatrix(view.clipFromView))
        fail("projection",
             "its planes give a non-finite projection matrix (left/right, bottom/top or near/far "
             "too close together or too large for double precision); choose a wider or smaller "
             "volume");
    if (!finiteMatrix(view.viewFromWorld))
        fail("camera", "eye and target give a non-finite view matrix; move them closer to the origin");
    return view;
}

bool leavesOutTheMinusOne(const Scene& scene) {
    return scene.perspectiveMatrix == PerspectiveMatrix::Unnegated &&
           scene.projection.type != ProjectionType::Orthographic;
}

glm::dmat4 worldFromObject(const SceneObject& object) {
    return glm::scale(glm::translate(glm::dmat4(1), object.center), object.radius * object.scale);
}

std::vector<std::string> sceneWarnings(const Scene& scene) {
    std::vector<std::string> warnings;
    auto check = [&](const glm::dvec3& colour, const std::string& path) {
        if (std::max({colour.x, colour.y, colour.z}) > kSuspectColour)
            warnings.push_back(path + ": " + formatVec(colour) +
                               " has a component above 10; colours are linear 0..1 (0..255 values would need "
                               "dividing by 255)");
    };
    check(scene.background, "image.background");
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const std::string path = "objects[" + std::to_string(i) + "].material.";
        check(scene.objects[i].material.ambient, path + "ambient");
        check(scene.objects[i].material.diffuse, path + "diffuse");
        check(scene.objects[i].material.specular, path + "specular");
        // A model's zero-area triangles have no normal and are left out (scene/model.h): say how many, so
        // that a hole in the picture has its reason on the terminal.
        if (const auto& model = scene.objects[i].model; model && model->trianglesDropped > 0)
            warnings.push_back("objects[" + std::to_string(i) +
                               "].mesh: " + std::to_string(model->trianglesDropped) + " zero-area triangle" +
                               (model->trianglesDropped == 1 ? "" : "s") + " of " + printable(model->path) +
                               " left out (they have no normal)");
    }
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        const std::string path = "lights[" + std::to_string(i) + "].";
        check(scene.lights[i].ambient, path + "ambient");
        check(scene.lights[i].diffuse, path + "diffuse");
        check(scene.lights[i].specular, path + "specular");
    }
    return warnings;
}

} // namespace shadelab
