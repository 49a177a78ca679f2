#include "app/measure/memory_budget.h"
#include "app/measure/shape_levels.h"

#include <algorithm>
#include <cstdint>
#include <set>
#include <utility>
#include <vector>

#include "shadelab/diagram/overlay.h"
#include "shadelab/geometry/mesh_layout.h"
#include "shadelab/geometry/sphere.h"
#include "shadelab/geometry/teapot.h"
#include "shadelab/scene/model.h"

namespace shadelab::app {

std::string sizeText(const Scene& scene) {
    return std::to_string(scene.width) + "x" + std::to_string(scene.height);
}

double renderBytes(const Scene& scene) {
    const double pixels = double(scene.width) * scene.height;
    // RGBA8 colour + 32-bit depth renderbuffers, the RGBA8 read-back, the Image and the PNG's RGB rows.
    double bytes = pixels * (4 + 4 + 4 + 4 + 3);
    // The teaching views' own targets (gl/views.cpp): RGBA32F textures with 32-bit depth — the mode's and
    // exact's renders, the error view's compare pass (its reduction adds a fifteenth), the profile's
    // wireframe render.
    constexpr double kFloatTarget = 16 + 4; // an RGBA32F texture and its 32-bit depth
    constexpr double kFloatColour = 16;     // the compare pass: an RGBA32F texture without depth
    if (scene.view.kind == ViewKind::Error)
        bytes += pixels * (kFloatTarget + kFloatTarget + kFloatColour) * 16.0 / 15.0;
    if (scene.view.kind == ViewKind::Profile) bytes += pixels * 3 * kFloatTarget;
    const MeshLayout layout = scene.shading == ShadingMode::Flat ? MeshLayout::Flat : MeshLayout::Smooth;
    // Each distinct mesh once: a shape at a level ("auto" counted at the shape's finest), or a model.
    std::set<std::pair<Shape, int>> levels;
    std::set<const Model*> models;
    for (const SceneObject& object : scene.objects) {
        if (object.shape == Shape::Mesh) {
            if (object.model) models.insert(object.model.get());
            continue;
        }
        const int finest = finestLevel(object.shape);
        // A sphere's absurd level (asked for by mistake) gives a huge figure; the teapot has no finer mesh.
        const int level = object.subdivisions == kAutoSubdivisions ? finest
                          : object.shape == Shape::Teapot          ? std::min(object.subdivisions, finest)
                                                                   : object.subdivisions;
        levels.emplace(object.shape, level);
    }
    // The vertex arrays of each mesh's layout (mesh_layout.h), as their buffers hold them.
    const auto arrayBytes = [layout](double vertices, double triangles) {
        return layout == MeshLayout::Flat
                   ? triangles * 3 * double(sizeof(FlatVertex))
                   : vertices * double(sizeof(SmoothVertex)) + triangles * 3 * double(sizeof(std::uint32_t));
    };
    struct Counted {
        double vertices, triangles, arrays;
    };
    std::vector<Counted> meshes;
    for (const auto& [shape, level] : levels) {
        if (shape == Shape::Teapot) {
            const double v = double(teapotVertexCount(level)), t = double(teapotTriangleCount(level));
            meshes.push_back({v, t, arrayBytes(v, t)});
        } else {
            meshes.push_back({double(sphereVertexCount(level)), double(sphereTriangleCount(level)),
                              meshBytes(level, layout)});
        }
    }
    for (const Model* model : models) {
        const double v = double(model->mesh.positions.size()), t = double(model->mesh.triangles.size());
        meshes.push_back({v, t, arrayBytes(v, t)});
    }
    for (const auto& [vertices, triangles, arrays] : meshes) {
        bytes += arrays;
        // The overlay's lines (overlay.h: two LineVertex a segment), on the CPU and in their buffer:
        // every edge (1.5 per triangle), and with normals one segment per face and per vertex.
        double segments = 0;
        if (scene.overlay == Overlay::Wireframe || scene.overlay == Overlay::Normals)
            segments += 1.5 * triangles;
        if (scene.overlay == Overlay::Normals) segments += triangles + vertices;
        bytes += segments * 2 * double(sizeof(LineVertex)) * 2;
    }
    return bytes;
}

double referenceBytes(const Scene& scene) {
    // The process without GL, then per pixel the float colour (16 bytes), the object id (4), the 8-bit
    // image (4) and the PNG's RGB rows (3).
    return kProcessBaselineBytes + double(scene.width) * scene.height * (16 + 4 + 4 + 3);
}

} // namespace shadelab::app
