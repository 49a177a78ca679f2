// What the panel edits (an object's material, scale and shininess, the view volume) and the names and
// figures it shows: DemoState's part that the window's panel and the page's controls call.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/demo/demo_format.h"
#include "app/demo/demo_state.h"
#include "shadelab/errors.h"
#include "shadelab/geometry/teapot.h"
#include "shadelab/scene/auto_level.h"

namespace shadelab::app {

void DemoState::setShininess(std::size_t object, double exponent) {
    exponents_[object] = exponent;
    scene_.objects[object].material.shininess = std::max(1.0, exponent); // DESIGN §3: exponents >= 1
    drawn_.stale = true;
}

double DemoState::presetExponent(double alpha) const {
    return window_.matchHighlight && scene_.lighting == LightingModel::BlinnPhong ? 4 * alpha : alpha;
}

int DemoState::level() const {
    return scene_.objects.empty() ? 0 : subdivisionLevel(drawn(), scene_.objects[0]);
}

bool DemoState::autoLevel() const {
    return !scene_.objects.empty() && scene_.objects[0].subdivisions == kAutoSubdivisions;
}

bool DemoState::setLevel(int wanted) {
    // The levels move together by the first object's difference, as + and − pressed that many times do,
    // but checked once: a level the limits refuse leaves every object where it was.
    if (scene_.objects.empty() || wanted == level()) return true;
    if (scene_.objects[0].shape == Shape::Teapot)
        checkTeapotLevel(wanted, "level");
    else
        checkSubdivisionLevel(wanted, "level");
    changeLevels(wanted - level());
    return levelRefusal_.empty();
}

void DemoState::setAutoLevel(bool on) {
    if (on == autoLevel()) return;
    const Scene& shown = drawn(); // off: each object keeps the level auto showed
    for (SceneObject& o : scene_.objects)
        o.subdivisions = on ? kAutoSubdivisions : subdivisionLevel(shown, o);
    drawn_.stale = true;
}

Shape DemoState::shape() const {
    const auto shown = shownObject();
    return shown ? scene_.objects[*shown].shape : Shape::Sphere;
}

void DemoState::setShape(Shape shape) {
    const auto shown = shownObject();
    if (!shown || shape == Shape::Mesh) return;
    // Made on a copy and checked as a scene file's values and limits are (a teapot at level 8 is 4.2 M
    // triangles), then kept.
    Scene edited = scene_;
    for (std::size_t i = 0; i < edited.objects.size(); ++i) {
        SceneObject& o = edited.objects[i];
        if (editedObject_ != kAllObjects && i != *shown) continue;
        if (o.shape == Shape::Mesh) { // a dropped or scene model becomes the shape, keeping its material
            o.mesh.clear();
            o.model.reset();
            o.closed = false;
            o.materialGiven = true;
        }
        o.shape = shape;
        if (o.subdivisions != kAutoSubdivisions)
            o.subdivisions = std::min(o.subdivisions, finestLevel(shape));
    }
    validateSceneValues(edited);
    checkSceneLimits(edited);
    scene_.objects = std::move(edited.objects);
    drawn_.stale = true;
}

void DemoState::setOrthographic(bool on) {
    if (on == orthographic_) return;
    orthographic_ = on;
    drawn_.stale = true;
}

std::string DemoState::materialName() const {
    const std::string name =
        material_ == 0 ? "scene's own" : std::string(materialPresets()[std::size_t(material_ - 1)].name);
    return materialEdited_ ? name + ", edited in the panel" : name;
}

std::string DemoState::editedObjectName() const {
    const std::size_t count = scene_.objects.size();
    if (count == 1) return "the object";
    if (editedObject_ == kAllObjects || editedObject_ < 0 || std::size_t(editedObject_) >= count)
        return "all " + std::to_string(count) + " objects";
    return "object " + std::to_string(editedObject_ + 1) + " of " + std::to_string(count);
}

void DemoState::chooseEditedObject(int number) {
    const int count = int(scene_.objects.size());
    editedObject_ = number <= 0 || count == 0 ? kAllObjects : std::min(number, count) - 1;
}

std::optional<std::size_t> DemoState::shownObject() const {
    if (scene_.objects.empty()) return std::nullopt;
    return std::size_t(std::clamp(editedObject_, 0, int(scene_.objects.size()) - 1)); // all: the first
}

void DemoState::editMaterial(const Material& edited) {
    const auto shown = shownObject();
    if (!shown) return;
    const Material before = scene_.objects[*shown].material;
    // Checked as a scene file's material is, at the first object it goes to (the refusal names it).
    Scene check;
    check.objects = {scene_.objects[editedObject_ == kAllObjects ? 0 : *shown]};
    check.objects[0].material = edited;
    try {
        validateSceneValues(check);
    } catch (const InputError& e) {
        const std::string message = e.what(); // "objects[0].material...": the object's own index instead
        const std::string index = std::to_string(editedObject_ == kAllObjects ? 0 : *shown);
        throw InputError(message.rfind("objects[0]", 0) == 0 ? "objects[" + index + "]" + message.substr(10)
                                                             : message);
    }
    if (editedObject_ != kAllObjects) {
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
    drawn_.stale = true;
}

void DemoState::editScale(const glm::dvec3& scale) {
    const auto shown = shownObject();
    if (!shown) return;
    // The edit is made on a copy and checked as a scene file's values are (a zero or infinite component, a
    // semi-axis 32-bit float cannot carry, an object too thin for exact shading at its distance), then kept.
    Scene edited = scene_;
    const glm::dvec3 before = edited.objects[*shown].scale;
    if (editedObject_ != kAllObjects) {
        edited.objects[*shown].scale = scale;
    } else { // as editMaterial: only the component that changed, on every object
        for (SceneObject& o : edited.objects)
            for (int i = 0; i < 3; ++i)
                if (scale[i] != before[i]) o.scale[i] = scale[i];
    }
    validateSceneValues(edited);
    scene_.objects = std::move(edited.objects);
    drawn_.stale = true;
}

void DemoState::editViewVolume(const Projection& edited) {
    Scene check = drawn();
    check.projection = edited;
    validateSceneValues(check);
    initial_.projection = edited;
    scene_.projection = edited;
    orthographic_ = edited.type == ProjectionType::Orthographic;
    volumeDistance_ = glm::length(check.eye - check.target);
    drawn_.stale = true;
}

Scene DemoState::valuesCopy() {
    // The objects (up to 10,000) are moved aside for the copy and back, never copied.
    std::vector<SceneObject> objects = std::move(scene_.objects);
    scene_.objects.clear();
    try {
        Scene values = scene_;
        scene_.objects = std::move(objects);
        return values;
    } catch (...) {
        scene_.objects = std::move(objects);
        throw;
    }
}

void DemoState::keepValues(Scene edited) {
    edited.objects = std::move(scene_.objects);
    try {
        validateSceneValues(edited);
    } catch (...) {
        scene_.objects = std::move(edited.objects);
        throw;
    }
    scene_ = std::move(edited);
    drawn_.stale = true;
}

std::string DemoState::lightsName() const {
    return lights_ == 0 ? "scene's own" : std::string(lightPresets()[std::size_t(lights_ - 1)].name);
}

std::size_t DemoState::triangleCount() const {
    const Scene& scene = drawn();
    std::size_t total = 0;
    for (const SceneObject& o : scene.objects)
        total += shadelab::triangleCount(o, subdivisionLevel(scene, o));
    return total;
}

} // namespace shadelab::app
