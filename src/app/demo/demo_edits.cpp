// What the panel edits (an object's material, scale and shininess, the view volume) and the names and
// figures it shows: DemoState's part that the window's panel and the page's controls call.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/demo/demo_format.h"
#include "app/demo/demo_state.h"
#include "shadelab/errors.h"
#include "shadelab/geometry/subdivision.h"

namespace shadelab::app {

void DemoState::setShininess(std::size_t object, double exponent) {
    exponents_[object] = exponent;
    scene_.objects[object].material.shininess = std::max(1.0, exponent); // DESIGN §3: exponents >= 1
}

double DemoState::presetExponent(double alpha) const {
    return matchHighlight && scene_.lighting == LightingModel::BlinnPhong ? 4 * alpha : alpha;
}

int DemoState::level() const {
    return scene_.objects.empty() ? 0 : subdivisionLevel(drawn(), scene_.objects[0]);
}

bool DemoState::autoLevel() const {
    return !scene_.objects.empty() && scene_.objects[0].subdivisions == kAutoSubdivisions;
}

std::string DemoState::materialName() const {
    const std::string name =
        material_ == 0 ? "scene's own" : std::string(materialPresets()[std::size_t(material_ - 1)].name);
    return materialEdited_ ? name + ", edited in the panel" : name;
}

std::string DemoState::editedObjectName() const {
    const std::size_t count = scene_.objects.size();
    if (count == 1) return "the object";
    if (editedObject == kAllObjects || editedObject < 0 || std::size_t(editedObject) >= count)
        return "all " + std::to_string(count) + " objects";
    return "object " + std::to_string(editedObject + 1) + " of " + std::to_string(count);
}

void DemoState::chooseEditedObject(int number) {
    const int count = int(scene_.objects.size());
    editedObject = number <= 0 || count == 0 ? kAllObjects : std::min(number, count) - 1;
}

std::optional<std::size_t> DemoState::shownObject() const {
    if (scene_.objects.empty()) return std::nullopt;
    return std::size_t(std::clamp(editedObject, 0, int(scene_.objects.size()) - 1)); // all: the first
}

void DemoState::editMaterial(const Material& edited) {
    const auto shown = shownObject();
    if (!shown) return;
    const Material before = scene_.objects[*shown].material;
    if (editedObject != kAllObjects) {
        scene_.objects[*shown].material = edited;
    } else {
        for (SceneObject& o : scene_.objects) {
            Material& m = o.material;
            if (edited.ambient != before.ambient) m.ambient = edited.ambient;
            if (edited.diffuse != before.diffuse) m.diffuse = edited.diffuse;
            if (edited.specular != before.specular) m.specular = edited.specular;
            if (edited.shininess != before.shininess) m.shininess = edited.shininess;
        }
    }
    materialEdited_ = true;
}

void DemoState::editScale(const glm::dvec3& scale) {
    const auto shown = shownObject();
    if (!shown) return;
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(scale[i]) || scale[i] == 0) {
            char value[32];
            std::snprintf(value, sizeof value, "%g", scale[i]);
            throw InputError("objects[" + std::to_string(*shown) + "].scale[" + std::to_string(i) +
                             "]: must be finite and non-zero, got " + value);
        }
    // The edit is made on a copy and checked as a scene file's values are (a semi-axis 32-bit float cannot
    // carry, an object too thin for exact shading at its distance), then kept.
    Scene edited = scene_;
    const glm::dvec3 before = edited.objects[*shown].scale;
    if (editedObject != kAllObjects) {
        edited.objects[*shown].scale = scale;
    } else { // as editMaterial: only the component that changed, on every object
        for (SceneObject& o : edited.objects)
            for (int i = 0; i < 3; ++i)
                if (scale[i] != before[i]) o.scale[i] = scale[i];
    }
    validateSceneValues(edited);
    scene_.objects = std::move(edited.objects);
}

void DemoState::editViewVolume(const Projection& edited) {
    Scene check = drawn();
    check.projection = edited;
    validateSceneValues(check);
    initial_.projection = edited;
    scene_.projection = edited;
    orthographic_ = edited.type == ProjectionType::Orthographic;
    volumeDistance_ = glm::length(check.eye - check.target);
}

std::string DemoState::lightsName() const {
    return lights_ == 0 ? "scene's own" : std::string(lightPresets()[std::size_t(lights_ - 1)].name);
}

std::size_t DemoState::triangleCount() const {
    const Scene scene = drawn();
    std::size_t total = 0;
    for (const SceneObject& o : scene.objects) total += sphereTriangleCount(subdivisionLevel(scene, o));
    return total;
}

} // namespace shadelab::app
