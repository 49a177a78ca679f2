// Scene → JSON (DESIGN §4): every field written, doubles in shortest round-trip form, so that parseScene
// reads the text back to the same scene. The demo saves it beside each screenshot.
#include <cerrno>
#include <cstdio>
#include <string>
#include <system_error>

#include <nlohmann/json.hpp>

#include "scene/scene_internal.h"
#include "shadelab/io/atomic_file.h"
#include "shadelab/scene/scene_file.h"

namespace shadelab {

using detail::Json;

namespace {

Json toJson(const glm::dvec3& v) {
    return Json::array({v.x, v.y, v.z});
}

Json toJson(const Projection& p) {
    Json json = {{"type", toString(p.type)}, {"near", p.near}, {"far", p.far}};
    if (p.type == ProjectionType::Perspective) {
        json["fovy_deg"] = p.fovyDeg;
    } else {
        json["left"] = p.left;
        json["right"] = p.right;
        json["bottom"] = p.bottom;
        json["top"] = p.top;
    }
    return json;
}

Json toJson(const Material& m) {
    return {{"ambient", toJson(m.ambient)},
            {"diffuse", toJson(m.diffuse)},
            {"specular", toJson(m.specular)},
            {"shininess", m.shininess}};
}

// A sphere is written without "shape", as scenes were before there were other shapes, so their saved text
// stays the same. A mesh object writes its file and "closed" (no shape, no level: the file's), and its
// material only when the scene gave one: otherwise it is the file's, read again with it.
Json toJson(const SceneObject& o) {
    Json json = {{"center", toJson(o.center)}, {"radius", o.radius}, {"scale", toJson(o.scale)}};
    if (o.shape == Shape::Mesh) {
        json["mesh"] = o.mesh;
        json["closed"] = o.closed;
        if (o.materialGiven) json["material"] = toJson(o.material);
        return json;
    }
    if (o.shape != Shape::Sphere) json["shape"] = toString(o.shape);
    json["subdivisions"] = o.subdivisions == kAutoSubdivisions ? Json("auto") : Json(o.subdivisions);
    json["material"] = toJson(o.material);
    return json;
}

// Only the keys the light's type reads: the others are errors in a scene file.
Json toJson(const Light& l) {
    Json json = {{"type", toString(l.type)}, {"ambient", toJson(l.ambient)}};
    if (l.type == LightType::Ambient) return json;
    json["diffuse"] = toJson(l.diffuse);
    json["specular"] = toJson(l.specular);
    if (detail::hasPosition(l.type)) {
        json["position"] = toJson(l.position);
        json["attenuation"] = toJson(l.attenuation);
    }
    if (detail::hasDirection(l.type)) json["direction"] = toJson(l.direction);
    if (l.type == LightType::Spot) {
        json["cutoff_deg"] = l.cutoffDeg;
        json["exponent"] = l.exponent;
    }
    return json;
}

} // namespace

std::string sceneToJson(const Scene& scene) {
    Json objects = Json::array(), lights = Json::array();
    for (const SceneObject& o : scene.objects) objects.push_back(toJson(o));
    for (const Light& l : scene.lights) lights.push_back(toJson(l));
    Json root = {
        {"image",
         {{"width", scene.width}, {"height", scene.height}, {"background", toJson(scene.background)}}},
        {"camera", {{"eye", toJson(scene.eye)}, {"target", toJson(scene.target)}, {"up", toJson(scene.up)}}},
        {"projection", toJson(scene.projection)},
        {"perspective_matrix", toString(scene.perspectiveMatrix)},
        {"shading", toString(scene.shading)},
        {"lighting", toString(scene.lighting)},
        {"term", toString(scene.term)},
        {"toon_bands", scene.toonBands},
        {"tolerance_px", scene.tolerancePx},
        {"depth", toString(scene.depth)},
        {"vertex_normals", toString(scene.vertexNormals)},
        {"normal_matrix", toString(scene.normalMatrix)},
        {"overlay", toString(scene.overlay)},
        {"view", toString(scene.view)},
        {"objects", objects},
        {"lights", lights}};
    if (scene.view.at) root["view_at"] = *scene.view.at;
    if (observed(scene.view.kind) || scene.view.observer != Observer{})
        root["view_observer"] = {scene.view.observer.azimuthDeg, scene.view.observer.elevationDeg,
                                 scene.view.observer.zoom};
    return root.dump(2) + "\n";
}

void saveScene(const Scene& scene, const std::filesystem::path& path) {
    const std::string text = sceneToJson(scene);
    writeFileAtomically(path, "scene", [&](std::FILE* file) {
        if (std::fwrite(text.data(), 1, text.size(), file) != text.size())
            failWrite("scene", path, std::generic_category().message(errno));
    });
}

} // namespace shadelab
