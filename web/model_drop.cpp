// A model file dropped on the page or picked with its input (docs/DESIGN.md §1, "Meshes from files"): the
// main file (.obj, .gltf, .glb) read by the loader the command line uses (scene/model.h parseModel), its
// MTL or glTF buffers served by name from the files dropped with it, and the chosen object made a mesh
// object of that model. The page's files have names but no folders, so a side file is found by its name.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <emscripten/emscripten.h>
#include <nlohmann/json.hpp>

#include "page_state.h"
#include "shadelab/errors.h"
#include "shadelab/scene/model.h"
#include "shadelab/scene/scene.h"

namespace shadelab::web {
namespace {

struct DroppedFile {
    std::string name;
    std::string_view bytes; // in the page's heap, alive for the call (page_model.js frees it after)
};

std::string_view lastPart(std::string_view path) {
    const std::size_t slash = path.find_last_of("/\\");
    return slash == std::string_view::npos ? path : path.substr(slash + 1);
}

// The side file the model names: the dropped file of that exact name, else of its last part
// ("materials/cube.mtl" is the dropped "cube.mtl": a drop carries no folders). Whether a name may leave the
// model's folder at all is the loader's check, made before it asks.
std::optional<std::string> sideFile(void* context, std::string_view relativeName) {
    const auto& files = *static_cast<const std::vector<DroppedFile>*>(context);
    for (const DroppedFile& file : files)
        if (file.name == relativeName) return std::string(file.bytes);
    for (const DroppedFile& file : files)
        if (file.name == lastPart(relativeName)) return std::string(file.bytes);
    return std::nullopt;
}

// The edited object (every object when all are edited, DemoState::editedObject) becomes a mesh object of
// `model`, named `name` as a scene file would name it; without a material of the file's it keeps its own.
// The whole scene is checked (values and limits: a model's triangles count) before it is kept, so a refusal
// leaves the scene as it was.
void becomeModel(DemoState& state, const std::shared_ptr<const Model>& model, const std::string& name) {
    if (state.scene().objects.empty())
        throw InputError(name + ": the scene has no object to become the model; open a scene with one");
    Scene edited = state.scene();
    for (std::size_t i = 0; i < edited.objects.size(); ++i) {
        if (state.editedObject() != DemoState::kAllObjects && std::size_t(state.editedObject()) != i)
            continue;
        SceneObject& object = edited.objects[i];
        object.shape = Shape::Mesh;
        object.mesh = name;
        object.model = model;
        object.closed = false; // a dropped model may be open: drawn two-sided (DESIGN §1)
        object.materialGiven = !model->material;
        if (model->material) object.material = *model->material;
    }
    validateScene(edited);
    state.editScene() = std::move(edited);
}

} // namespace
} // namespace shadelab::web

using namespace shadelab;
using namespace shadelab::web;

extern "C" {

// `files`: a JSON array of {"name", "pointer", "size"}, the dropped files' bytes in the heap, the model's
// main file first. "" when the chosen object shows the model, else the loader's message (the file and line
// of an OBJ, the JSON path of a glTF) or the scene check's, with nothing changed.
EMSCRIPTEN_KEEPALIVE const char* shadelab_load_model(const char* files) {
    return guarded([&] {
        std::vector<DroppedFile> dropped;
        for (const nlohmann::json& file : nlohmann::json::parse(files)) {
            const auto* bytes = reinterpret_cast<const char*>(file.at("pointer").get<std::uintptr_t>());
            dropped.push_back({file.at("name").get<std::string>(),
                               std::string_view(bytes, file.at("size").get<std::size_t>())});
        }
        if (dropped.empty()) throw InputError("no model file was given");
        const std::string name = dropped.front().name;
        const std::shared_ptr<const Model> model =
            parseModel(dropped.front().bytes, name, sideFile, &dropped);
        becomeModel(*page().state, model, name);
        requestDraw();
    });
}

} // extern "C"
