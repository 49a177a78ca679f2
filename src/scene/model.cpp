// Models from files (scene/model.h): which reader a name picks, the checks every reader's output passes
// (finishModel), the file system's part (what may be opened, and which side files), and a scene's models.
#include "shadelab/scene/model.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <system_error>

#include "scene/model_internal.h"
#include "shadelab/errors.h"
#include "shadelab/io/text.h"

namespace shadelab {
namespace detail {
namespace {

[[noreturn]] void refuse(std::string_view name, std::string_view where, const std::string& what) {
    throw InputError(printable(name) + ": " + (where.empty() ? "" : std::string(where) + ": ") + what);
}

bool finite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

std::string lowerExtension(std::string_view name) {
    std::string extension = std::filesystem::path(std::string(name)).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return extension;
}

} // namespace

std::optional<std::string> outsideTheFolder(std::string_view relativeName) {
    if (relativeName.empty()) return "is empty";
    if (relativeName.find('\0') != std::string_view::npos) return "holds a NUL character";
    if (relativeName.front() == '/' || relativeName.front() == '\\') return "is an absolute path";
    if (relativeName.find(':') != std::string_view::npos) return "names a drive or a scheme";
    std::size_t start = 0;
    while (start <= relativeName.size()) {
        const std::size_t end = std::min(relativeName.find_first_of("/\\", start), relativeName.size());
        if (relativeName.substr(start, end - start) == "..") return "leaves the model's folder (\"..\")";
        start = end + 1;
    }
    return std::nullopt;
}

std::string readSideFile(SideFileReader reader, void* context, std::string_view relativeName,
                         std::string_view name, std::string_view field) {
    if (const std::optional<std::string> why = outsideTheFolder(relativeName))
        refuse(name, field,
               quotedValue(relativeName) + " " + *why +
                   ": a model reads only files in its own folder or below; put it beside the model");
    std::optional<std::string> bytes = reader ? reader(context, relativeName) : std::nullopt;
    if (!bytes) refuse(name, field, "cannot read " + quotedValue(relativeName) + ": put it beside the model");
    return std::move(*bytes);
}

Model finishModel(RawMesh raw, std::string_view name) {
    if (raw.positions.size() > kMaxModelVertices)
        refuse(name, "",
               std::to_string(raw.positions.size()) + " vertices; at most " +
                   std::to_string(kMaxModelVertices) + " are allowed: decimate or split the model");
    for (std::size_t t = 0; t < raw.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k)
            if (raw.triangles[t][k] >= raw.positions.size())
                refuse(name, "",
                       "a triangle's vertex index " + std::to_string(raw.triangles[t][k]) +
                           " is out of range (" + std::to_string(raw.positions.size()) + " vertices)");
    if (raw.material)
        for (const glm::dvec3* c : {&raw.material->ambient, &raw.material->diffuse, &raw.material->specular})
            if (!finite(*c) || c->x < 0 || c->y < 0 || c->z < 0)
                refuse(name, "", "the material's colours must be finite and >= 0 (linear RGB)");
    Model model;
    model.path = std::string(name);
    model.material = raw.material;
    TriangleMesh& mesh = model.mesh;
    mesh.positions = std::move(raw.positions);
    for (const glm::dvec3& p : mesh.positions)
        if (!finite(p)) refuse(name, "", "a vertex position is not a finite number");
    // Zero-area triangles (two corners alike, or three in a line) have no normal and cover nothing.
    mesh.triangles.reserve(raw.triangles.size());
    mesh.faceNormals.reserve(raw.triangles.size());
    std::vector<glm::dvec3> areaWeighted(raw.normals.empty() ? mesh.positions.size() : 0, glm::dvec3(0));
    for (const glm::uvec3& t : raw.triangles) {
        const glm::dvec3 cross =
            glm::cross(mesh.positions[t.y] - mesh.positions[t.x], mesh.positions[t.z] - mesh.positions[t.x]);
        const double length = glm::length(cross);
        if (!(length > 0) || !std::isfinite(length)) {
            ++model.trianglesDropped;
            continue;
        }
        mesh.triangles.push_back(t);
        mesh.faceNormals.push_back(cross / length);
        // |cross| is twice the area: summing the unnormalized cross products weighs each face by its area.
        if (!areaWeighted.empty())
            for (int k = 0; k < 3; ++k) areaWeighted[t[k]] += cross;
    }
    if (mesh.triangles.empty())
        refuse(name, "",
               raw.triangles.empty()
                   ? "no triangles: a model needs faces (OBJ \"f\", glTF TRIANGLES)"
                   : "no triangle has an area (all " + std::to_string(raw.triangles.size()) +
                         " are degenerate): the model is empty");
    if (raw.normals.empty()) {
        model.normalsMade = true;
        mesh.vertexNormals.resize(mesh.positions.size());
        for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
            const double length = glm::length(areaWeighted[v]);
            // A vertex no face uses, or whose faces cancel: any unit normal draws the same.
            mesh.vertexNormals[v] = length > 0 ? areaWeighted[v] / length : glm::dvec3(0, 1, 0);
        }
    } else {
        mesh.vertexNormals = std::move(raw.normals);
        for (glm::dvec3& n : mesh.vertexNormals) {
            const double length = glm::length(n);
            if (!finite(n) || !(length > 0))
                refuse(name, "",
                       "a vertex normal is zero or not a finite number: fix it, or leave normals "
                       "out and shadelab makes them");
            n /= length;
        }
    }
    return model;
}

} // namespace detail

std::shared_ptr<const Model> parseModel(std::string_view bytes, std::string_view name,
                                        SideFileReader sideFile, void* context) {
    const std::string extension = detail::lowerExtension(name);
    if (extension == ".obj")
        return std::make_shared<const Model>(detail::parseObj(bytes, name, sideFile, context));
    if (extension == ".gltf" || extension == ".glb")
        return std::make_shared<const Model>(
            detail::parseGltf(bytes, name, extension == ".glb", sideFile, context));
    detail::refuse(name, "", "not a model file shadelab reads: use .obj (with its .mtl), .gltf or .glb");
}

namespace {

// What may be opened as a model or beside it: a regular file (following symlinks) no larger than
// kMaxModelBytes. A folder, FIFO or device is refused before it is opened, so nothing blocks on it.
std::string readRegularFile(const std::filesystem::path& file, std::string_view name) {
    std::error_code error;
    const std::filesystem::file_status status = std::filesystem::status(file, error);
    if (error || !std::filesystem::exists(status))
        throw InputError(printable(name) + ": cannot read: no such file");
    if (std::filesystem::is_directory(status))
        throw InputError(printable(name) +
                         ": is a folder, not a model file: name the .obj, .gltf or .glb in it");
    if (!std::filesystem::is_regular_file(status))
        throw InputError(printable(name) +
                         ": is not a regular file (a FIFO, a device or a socket): name a model file");
    const auto size = std::filesystem::file_size(file, error);
    if (!error && size > kMaxModelBytes)
        throw InputError(printable(name) + ": larger than " + std::to_string(kMaxModelBytes >> 20) +
                         " MiB; decimate the model");
    std::ifstream in(file, std::ios::binary);
    if (!in) throw InputError(printable(name) + ": cannot read: " + std::generic_category().message(errno));
    // Read in one piece into a string of the file's size (a character-by-character copy took twice as long
    // on a 77 MB OBJ); a file that grows meanwhile is read to its end.
    std::string bytes(error ? 0 : std::size_t(size), '\0');
    in.read(bytes.data(), std::streamsize(bytes.size()));
    bytes.resize(std::size_t(in.gcount()));
    if (in) bytes.append(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    return bytes;
}

struct FolderReader {
    std::filesystem::path folder; // canonical
    std::string modelName;
};

// A side file of a model on disk: inside the model's folder after symlinks are resolved.
std::optional<std::string> readBeside(void* context, std::string_view relativeName) {
    const auto& reader = *static_cast<const FolderReader*>(context);
    std::error_code error;
    const std::filesystem::path file =
        std::filesystem::weakly_canonical(reader.folder / std::string(relativeName), error);
    if (error) return std::nullopt;
    const std::string folderText = reader.folder.string() + "/";
    if (file.string().compare(0, folderText.size(), folderText) != 0)
        throw InputError(
            printable(reader.modelName) + ": " + quotedValue(relativeName) +
            " leads out of the model's folder through a link: put the file itself beside the model");
    return readRegularFile(file, file.string());
}

} // namespace

std::shared_ptr<const Model> loadModel(const std::filesystem::path& file) {
    const std::string name = file.string();
    const std::string bytes = readRegularFile(file, name);
    std::error_code error;
    FolderReader reader{std::filesystem::weakly_canonical(file, error).parent_path(), name};
    if (error) reader.folder = file.parent_path();
    return parseModel(bytes, name, &readBeside, &reader);
}

void loadSceneModels(Scene& scene, const std::filesystem::path& sceneFolder, ModelCache& cache) {
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        SceneObject& object = scene.objects[i];
        if (object.shape != Shape::Mesh || object.model) continue;
        const std::filesystem::path file = sceneFolder / object.mesh;
        std::shared_ptr<const Model>& slot = cache[file.lexically_normal().string()];
        try {
            if (!slot) slot = loadModel(file);
        } catch (const InputError& e) {
            throw InputError("objects[" + std::to_string(i) + "].mesh: " + e.what());
        }
        object.model = slot;
        if (!object.materialGiven && slot->material) object.material = *slot->material;
        object.materialGiven = true; // written back as used, so that a saved scene draws the same
    }
}

void loadSceneModels(Scene& scene, const std::filesystem::path& sceneFolder) {
    ModelCache cache;
    loadSceneModels(scene, sceneFolder, cache);
}

} // namespace shadelab
