// The scene description shared by the window, `shadelab render`, the reference, the report and the tests
// (DESIGN §4). Parsing validates everything and names the JSON path of any bad value.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "shadelab/geometry/sphere.h"
#include "shadelab/scene/camera.h"
#include "shadelab/scene/view.h"
#include "shadelab/shading/lighting.h"

namespace shadelab {

enum class ProjectionType { Perspective, Frustum, Orthographic };

// "depth": standard is DESIGN §2's convention (NDC z in [−1, 1], near → +1, 24-bit depth, GL_GREATER);
// reversed is true reversed-Z ([0, 1] clip range, near → 1, 32-bit float depth, GL_GREATER), optionally
// with the far plane at infinity (reversed-infinite; `far` then only bounds the analytic reference).
enum class DepthMode { Standard, Reversed, ReversedInfinite };
std::string_view toString(DepthMode mode);      // "standard" | "reversed" | "reversed-infinite"
std::string_view toString(ProjectionType type); // "perspective" | "frustum" | "orthographic"

// "overlay": lines drawn over the shaded surface for teaching (the demo's W key): none; wireframe (the mesh's
// edges); normals (the edges, each face normal from its centroid and each vertex normal of the scene's
// kind). The analytic reference ignores it: it shows the mesh, not the sphere.
// lights: each light where it is (outside_view.h's markers: a point light a small wire sphere, a
// directional light arrows along its direction, a spot light its cone), in the camera's picture.
enum class Overlay { None, Wireframe, Normals, Lights };
std::string_view toString(Overlay overlay); // "none" | "wireframe" | "normals" | "lights"

// The vocabularies of this header (vocabulary.h): every spelling each accepts, in order.
inline constexpr std::array kProjectionTypes = {ProjectionType::Perspective, ProjectionType::Frustum,
                                                ProjectionType::Orthographic};
inline constexpr std::array kVertexNormals = {VertexNormals::Averaged, VertexNormals::Exact};
inline constexpr std::array kDepthModes = {DepthMode::Standard, DepthMode::Reversed,
                                           DepthMode::ReversedInfinite};
inline constexpr std::array kOverlays = {Overlay::None, Overlay::Wireframe, Overlay::Normals,
                                         Overlay::Lights};

struct Projection {
    ProjectionType type = ProjectionType::Perspective;
    double fovyDeg = 40;                               // perspective
    double left = -1, right = 1, bottom = -1, top = 1; // frustum (at the near plane), orthographic
    double near = 0.5, far = 20;                       // positive distances
    bool operator==(const Projection&) const = default;
};

// "subdivisions": "auto": the smallest level whose silhouette error stays below the scene's tolerance for
// the object's projected size (subdivision.h).
inline constexpr int kAutoSubdivisions = -1;

// "shape": what an object is (docs/DESIGN.md §1). A "mesh" object names a model file instead
// (scene/model.h), and has no shape or subdivisions of its own.
enum class Shape { Sphere, Teapot, Mesh };
std::string_view toString(Shape shape); // "sphere" | "teapot" | "mesh"
inline constexpr std::array kShapes = {Shape::Sphere, Shape::Teapot};

struct Model; // scene/model.h: a mesh read from a file, shared by every object that names the file

struct SceneObject {
    Shape shape = Shape::Sphere;
    glm::dvec3 center{0, 0, 0};
    double radius = 1;
    glm::dvec3 scale{1, 1, 1}; // non-uniform scale: an ellipsoid; negative components mirror
    int subdivisions = 5;      // 0..kMaxSubdivisions (the teapot's 0..kMaxTeapotLevel), or kAutoSubdivisions
    Material material;
    // Shape::Mesh: "mesh", the file as the scene spells it (relative to the scene file's folder), and the
    // model read from it (loadSceneModels, scene/model.h; null until then). "closed": the model encloses a
    // volume, so its back faces may be culled; an open one (the default, and the teapot) is drawn two-sided.
    std::string mesh;
    std::shared_ptr<const Model> model;
    bool closed = false;
    // False for a mesh object whose scene gave no "material": loadSceneModels then takes the file's.
    bool materialGiven = true;
    bool operator==(const SceneObject&) const = default;
};
// Whether back faces of `object` are hidden by its own front faces (the sphere; a model marked closed).
bool isClosed(const SceneObject& object);

inline constexpr int kMaxImageSize = 16384;
// The work one scene may ask for (docs/ci-engineers.md "Limits"): measured on 2 cores with llvmpipe, 1,000
// level-6 spheres (16.4 M triangles) render in 1.1 s and their reference (262 M ray tests) takes 2.2 s.
inline constexpr std::size_t kMaxObjects = 10000;
inline constexpr std::size_t kMaxTrianglesPerFrame = std::size_t(1) << 26;
inline constexpr std::uint64_t kMaxReferenceRayTests = std::uint64_t(1) << 32; // 64-bit also in wasm32
// What feeds the GPU's matrices and uniforms (projection planes and widths, semi-axes, attenuation, the
// distances of objects and lights from the eye) must lie in this magnitude range: they are 32-bit float
// there, and products of them must stay so.
inline constexpr double kMinFloatExtent = 1e-30, kMaxFloatExtent = 1e30;
// Exact shading ray-casts each object in 32-bit float in the units of its semi-axes, where the ray's origin
// and direction are squared: an object at most this many of its smallest semi-axes from the eye (the
// square, 1e36, stays below float's 3.4e38; measured: [1, 1, 1e-19] at distance 4 draws, 1e-20 drew
// nothing).
inline constexpr double kMaxRayCastReach = 1e18;
// With standard depth, no object may reach farther than this many near distances from the eye (their depth
// near/d rounds to 0, the clear value, and GL_GREATER drops them: measured onset about 3e7).
inline constexpr double kMaxStandardDepthRatio = 1e7;
inline constexpr double kMinFovyDeg = 1e-6; // projection.fovy_deg: narrower views overflow float

struct Scene {
    int width = 512, height = 512;
    glm::dvec3 background{0, 0, 0};
    glm::dvec3 eye{0, 0, 4}, target{0, 0, 0}, up{0, 1, 0};
    Projection projection;
    ShadingMode shading = ShadingMode::Phong;
    LightingModel lighting = LightingModel::BlinnPhong;
    LightingTerm term = LightingTerm::All; // "term": the whole lighting sum or one of its terms
    // "normal_matrix": inverse-transpose, or model (normals by M: the lecture's wrong picture, on purpose)
    NormalMatrixRule normalMatrix = NormalMatrixRule::InverseTranspose;
    // "perspective_matrix": webgl, or unnegated (before the −1: nothing in front of the eye survives
    // clipping)
    PerspectiveMatrix perspectiveMatrix = PerspectiveMatrix::WebGl;
    int toonBands = kToonBands; // "toon_bands": diffuse bands of toon shading, kMinToonBands..kMaxToonBands
    double tolerancePx = 0.5;   // "tolerance_px": the silhouette error "auto" subdivision allows, > 0
    DepthMode depth = DepthMode::Standard;
    VertexNormals vertexNormals = VertexNormals::Averaged; // "vertex_normals": "averaged" | "exact"
    Overlay overlay = Overlay::None;                       // "overlay"
    View view;                                             // "view", "view_at" (view.h)
    std::vector<SceneObject> objects{SceneObject{}};
    std::vector<Light> lights{defaultLight()};

    bool operator==(const Scene&) const = default; // every value, e.g. to tell a changed view

    static Light defaultLight();
};

// Parses scene JSON text. `source` names the text in messages (a file name). Throws InputError with the
// JSON path, e.g. "scene.json: lights[1].attenuation[2]: must be >= 0, got -1".
Scene parseScene(std::string_view jsonText, std::string_view source = "scene");
// One object's material as a scene spells it ({"ambient": [..], "diffuse": .., "specular": .., "shininess":
// ..}), read and range-checked as parseScene reads objects[object].material, with the same messages (the
// page's material sliders: one object's values, not a whole scene of thousands).
Material parseMaterial(std::string_view jsonText, std::size_t object, std::string_view source = "scene");
// A scene's text is at most 16 MiB (kMaxSceneBytes): InputError "<name>: cannot read scene file: larger
// than 16 MiB; not a scene file" beyond it, as the command line says while it reads and the page before it
// parses.
inline constexpr std::size_t kMaxSceneBytes = std::size_t(16) << 20;
void checkSceneTextSize(std::size_t bytes, std::string_view name);

// The whole scene as JSON that parseScene reads back to the same scene (every field written, doubles in
// shortest round-trip form). The demo saves it beside each screenshot.
std::string sceneToJson(const Scene& scene);

// Valid but probably not meant: a colour component above kSuspectColour (colours are linear 0..1, and
// [200, 30, 30] reads as 0..255 and draws a white blob). One message per colour, naming its JSON path.
inline constexpr double kSuspectColour = 10;
std::vector<std::string> sceneWarnings(const Scene& scene);

// Checks the ranges of DESIGN §4 on a scene built in code or changed by flags (parseScene already does).
void validateScene(const Scene& scene);
// validateScene in two parts. The values: every range parseScene checks as it reads, and the camera. The
// limits: what depends on the whole composed scene (the work it asks for, docs/ci-engineers.md "Limits", and
// the depth range standard depth resolves); parseScene leaves them to validateScene, because flags applied
// after parsing (--subdivisions, --depth) may bring a scene within them.
void validateSceneValues(const Scene& scene);
void checkSceneLimits(const Scene& scene);

// Matrices derived from a scene, in double.
struct SceneView {
    glm::dmat4 viewFromWorld;
    glm::dmat4 clipFromView;
    ViewVolume volume;
    bool orthographic = false;
    DepthMode depth = DepthMode::Standard; // which clipFromView this is, and the depth set-up it needs

    // The clipper's test that only w decides: w > 0. Every point in front of the eye passes it with the
    // WebGL matrix, none with the unnegated one; the ray casts (the reference, exact shading, the probe) make
    // it as the rasterizer does.
    bool passesW(const glm::dvec3& positionView) const {
        return (clipFromView * glm::dvec4(positionView, 1.0)).w > 0;
    }
};
SceneView sceneView(const Scene& scene); // throws InputError for a degenerate camera or bad planes
// The scene drawn at width × height (a viewport's size, which the perspective aspect follows).
inline Scene atSize(Scene scene, int width, int height) {
    scene.width = width;
    scene.height = height;
    return scene;
}
// Whether sceneView leaves out the perspective matrix's −1 ("perspective_matrix": "unnegated" on a
// perspective or frustum projection; an orthographic one has no −1), so that everything is clipped.
bool leavesOutTheMinusOne(const Scene& scene);
glm::dmat4 worldFromObject(const SceneObject& object); // translate(center)·scale(radius·scale)

} // namespace shadelab
