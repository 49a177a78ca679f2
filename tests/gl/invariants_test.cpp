// Properties every rendering must have, whatever the reference images say: visibility by depth, flat
// triangles of one colour, and only finite, in-range colours on stiff scenes.
#include <functional>
#include <set>
#include <tuple>

#include <glm/gtc/matrix_transform.hpp>

#include "gl/gl_test_support.h"

namespace shadelab::test {
namespace {

glm::u8vec3 rgbAt(const Image& image, int x, int y) {
    const std::uint8_t* p = image.pixel(x, y);
    return {p[0], p[1], p[2]};
}

// A red sphere in front of a blue one, overlapping on screen. The nearer sphere must win wherever they
// overlap, whichever order they are drawn in: that is the depth test (GL_GREATER in DESIGN §2's convention).
TEST(Depth, NearerSphereHidesFartherOneInEitherDrawOrder) {
    SHADELAB_REQUIRE_GL(renderer);
    Scene scene = litSphereScene(128, LightType::Directional);
    scene.lights[0].ambient = {1, 1, 1};
    SceneObject nearRed, farBlue;
    nearRed.center = {-0.3, 0, 1};
    nearRed.radius = 0.6;
    nearRed.material = {{1, 0, 0}, {0, 0, 0}, {0, 0, 0}, 1};
    farBlue.center = {0.3, 0, -1};
    farBlue.material = {{0, 0, 1}, {0, 0, 0}, {0, 0, 0}, 1};
    for (const auto& objects : {std::vector{nearRed, farBlue}, std::vector{farBlue, nearRed}}) {
        scene.objects = objects;
        const ReferenceImage reference = renderReference(scene);
        const Image image = renderer->render(scene);
        const int nearId = objects[0].center.z > 0 ? 0 : 1;
        std::size_t overlapRed = 0, blueSeen = 0;
        const std::vector<bool> interior = interiorMask(reference.objectId, 128, 128, 1);
        for (int y = 0; y < 128; ++y) {
            for (int x = 0; x < 128; ++x) {
                const std::size_t i = std::size_t(y) * 128 + x;
                if (!interior[i]) continue;
                const glm::u8vec3 c = rgbAt(image, x, y);
                if (reference.objectId[i] == nearId) {
                    EXPECT_EQ(c, glm::u8vec3(255, 0, 0)) << "at " << x << "," << y;
                    ++overlapRed;
                } else {
                    EXPECT_EQ(c, glm::u8vec3(0, 0, 255)) << "at " << x << "," << y;
                    ++blueSeen;
                }
            }
        }
        EXPECT_GT(overlapRed, 1000u);
        EXPECT_GT(blueSeen, 500u);
        // The centre of the near sphere lies over the far one: red there proves the occlusion.
        EXPECT_EQ(rgbAt(image, 40, 64), glm::u8vec3(255, 0, 0));
    }
}

// DESIGN §3: flat shading is one colour per triangle. Project every front-facing triangle of a level-1
// sphere (big triangles) and check all pixel centres well inside it carry one colour.
TEST(Flat, EachTriangleInteriorIsOneColour) {
    SHADELAB_REQUIRE_GL(renderer);
    Scene scene = litSphereScene(256, LightType::Point);
    scene.shading = ShadingMode::Flat;
    scene.objects[0].subdivisions = 1;
    const Image image = renderer->render(scene);
    const SceneView view = sceneView(scene);
    const glm::dmat4 clipFromObject = view.clipFromView * view.viewFromWorld * worldFromObject(scene.objects[0]);
    const SphereMesh mesh = buildSphere(1);
    auto toWindow = [&](const glm::dvec3& p) {
        const glm::dvec4 clip = clipFromObject * glm::dvec4(p, 1);
        return glm::dvec2((clip.x / clip.w + 1) * 0.5 * 256, (1 - clip.y / clip.w) * 0.5 * 256);
    };
    int trianglesChecked = 0;
    for (const glm::uvec3& t : mesh.triangles) {
        const glm::dvec2 a = toWindow(mesh.positions[t.x]), b = toWindow(mesh.positions[t.y]),
                         c = toWindow(mesh.positions[t.z]);
        const double area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
        if (area > -200) continue; // back-facing (rows run down: front faces have negative area) or tiny
        std::set<std::tuple<int, int, int>> colours;
        int inside = 0;
        for (int y = 0; y < 256; ++y) {
            for (int x = 0; x < 256; ++x) {
                const glm::dvec2 p(x + 0.5, y + 0.5);
                // Distance to each edge, positive inside; 2 px margin keeps away from edge rasterization.
                auto edge = [&](glm::dvec2 u, glm::dvec2 v) {
                    const glm::dvec2 d = v - u;
                    return ((p.x - u.x) * d.y - (p.y - u.y) * d.x) / glm::length(d);
                };
                if (edge(a, b) < 2 || edge(b, c) < 2 || edge(c, a) < 2) continue;
                const glm::u8vec3 colour = rgbAt(image, x, y);
                colours.insert({colour.x, colour.y, colour.z});
                ++inside;
            }
        }
        if (inside < 20) continue;
        ++trianglesChecked;
        EXPECT_EQ(colours.size(), 1u) << "triangle " << t.x << "," << t.y << "," << t.z << " has "
                                      << colours.size() << " colours over " << inside << " pixels";
    }
    EXPECT_GE(trianglesChecked, 5); // of the 16 faces, about half face the camera; the rim ones are slivers
}

struct StiffCase {
    const char* name;
    std::function<void(Scene&)> change;
};

const StiffCase kStiffCases[] = {
    {"viewer_opposite_light", // v = −l at the silhouette: the light is straight behind the sphere
     [](Scene& s) { s.lights[0].position = {0, 0, -4}; }},
    {"shininess_1", [](Scene& s) { s.objects[0].material.shininess = 1; }},
    {"shininess_10000", [](Scene& s) { s.objects[0].material.shininess = 1e4; }},
    {"light_inside_sphere", [](Scene& s) { s.lights[0].position = {0.1, 0.2, 0.1}; }},
    {"light_on_surface_no_constant_attenuation",
     [](Scene& s) {
         s.lights[0].position = {0, 0, 1};
         s.lights[0].attenuation = {0, 0, 1};
     }},
    {"grazing_directional", [](Scene& s) {
         s.lights[0].type = LightType::Directional;
         s.lights[0].direction = {-1, 0, 0};
     }},
    {"very_bright", [](Scene& s) { s.lights[0].diffuse = s.lights[0].specular = {1e6, 1e6, 1e6}; }},
    {"spot_cutoff_0_and_90", [](Scene& s) {
         Light spot = s.lights[0];
         spot.type = LightType::Spot;
         spot.position = {0, 0, 3};
         spot.direction = {0, 0, -1};
         spot.cutoffDeg = 0;
         Light wide = spot;
         wide.cutoffDeg = 90;
         s.lights = {spot, wide};
     }},
};

class StiffScenes : public testing::TestWithParam<StiffCase> {};

// Rendered through a float target so a NaN or Inf cannot hide behind the 8-bit conversion.
TEST_P(StiffScenes, RenderOnlyFiniteInRangeColours) {
    SHADELAB_REQUIRE_GL(renderer);
    for (ShadingMode mode : kShadingModes) {
        for (LightingModel model : kLightingModels) {
            Scene scene = litSphereScene(96, LightType::Point);
            scene.shading = mode;
            scene.lighting = model;
            GetParam().change(scene);
            const ValueScan scan = scanValues(renderer->renderFloat(scene));
            EXPECT_EQ(scan.nonFinite, 0u) << toString(mode) << "/" << toString(model);
            EXPECT_EQ(scan.outOfRange, 0u) << toString(mode) << "/" << toString(model);
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Cases, StiffScenes, testing::ValuesIn(kStiffCases),
                         [](const auto& info) { return std::string(info.param.name); });

} // namespace
} // namespace shadelab::test
