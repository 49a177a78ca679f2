// Properties every rendering must have, whatever the reference images say: visibility by depth, flat
// triangles of one colour lit at the centroid, Gouraud colours clamped per vertex, and only finite,
// in-range colours as bright as the reference on stiff scenes; and the GL objects they are drawn with
// (handles and render targets) created, adopted and deleted as gl/handles.h and render_target.h say.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <set>
#include <tuple>
#include <vector>

#include <glad/gl.h>
#include <glm/gtc/matrix_transform.hpp>

#include "gl/gl_test_support.h"
#include "gl/projected_mesh.h"
#include "shadelab/errors.h"
#include "shadelab/gl/handles.h"
#include "shadelab/gl/render_target.h"

namespace shadelab::test {
namespace {

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

// DESIGN §3: Gouraud shading clamps each vertex colour, then interpolates (as fixed-function GL does).
// An over-bright light (diffuse 3×) drives vertex colours above 1 on a coarse sphere; well inside each
// front-facing triangle the pixel must be the perspective-correct barycentric blend of the three clamped
// vertex colours within ±2/255. Catches: clamping after interpolation (in the fragment stage) instead of per
// vertex — the test also shows that this would be off at many pixels — plus affine instead of
// perspective-correct interpolation, lighting with the wrong normal or position, and the wrong lighting
// model.
// DESIGN §3, through the shared check (gl/projected_mesh.h), which the browser test runs on WebGL 2 too.
TEST(Flat, EachTriangleIsOneColourLitAtItsCentroid) {
    SHADELAB_REQUIRE_GL(renderer);
    checkFlatLitAtCentroids([&](const Scene& scene) { return renderer->render(scene); });
}

TEST(Gouraud, InterpolatesClampedVertexColoursPerspectiveCorrectly) {
    SHADELAB_REQUIRE_GL(renderer);
    Scene scene = litSphereScene(256, LightType::Point);
    scene.lights[0].diffuse = {3, 3, 3};
    scene.shading = ShadingMode::Gouraud;
    scene.objects[0].subdivisions = 2;
    const ProjectedMesh pm(scene, 2);
    const Material& material = scene.objects[0].material;
    for (LightingModel model : kLightingModels) {
        SCOPED_TRACE(std::string(toString(model)));
        scene.lighting = model;
        const ShadeOptions options{model, false, scene.toonBands};
        std::vector<glm::dvec3> unclamped, clamped;
        for (std::size_t i = 0; i < pm.mesh.positions.size(); ++i) {
            unclamped.push_back(
                pm.shadeAt(pm.mesh.positions[i], pm.mesh.vertexNormals[i], material, options));
            clamped.push_back(clampColor(unclamped.back()));
        }
        const ImageF image = renderer->renderFloat(scene);
        std::size_t pixels = 0, failures = 0, clampLateWouldFail = 0;
        double worst = 0, worstClampLate = 0, worstAffine = 0;
        auto delta = [](glm::dvec3 u, glm::dvec3 v) { // max channel difference in 1/255 units
            const glm::dvec3 d = glm::abs(u - v) * 255.0;
            return std::max({d.x, d.y, d.z});
        };
        for (const glm::uvec3& t : pm.mesh.triangles) {
            const double w[3] = {pm.clip[t.x].w, pm.clip[t.y].w, pm.clip[t.z].w};
            auto blend = [&](const std::vector<glm::dvec3>& colours, glm::dvec3 weights) {
                return weights.x * colours[t.x] + weights.y * colours[t.y] + weights.z * colours[t.z];
            };
            auto check = [&](int x, int y, glm::dvec3 lambda) {
                // Perspective-correct weights: window-space barycentrics divided by each vertex's clip w.
                glm::dvec3 k(lambda.x / w[0], lambda.y / w[1], lambda.z / w[2]);
                k /= k.x + k.y + k.z;
                const glm::dvec3 expected = blend(clamped, k);
                const float* p = image.pixel(x, y);
                const glm::dvec3 actual(p[0], p[1], p[2]);
                const double e = delta(actual, expected);
                ++pixels;
                worst = std::max(worst, e);
                if (e > 2 && ++failures <= 5)
                    ADD_FAILURE() << "pixel " << x << "," << y << ": rendered " << actual.x << "," << actual.y
                                  << "," << actual.z << ", expected " << expected.x << "," << expected.y
                                  << "," << expected.z << " (" << e << "/255)";
                // What the wrong pipelines would give here.
                const double late = delta(clampColor(blend(unclamped, k)), expected);
                worstClampLate = std::max(worstClampLate, late);
                if (late > 2) ++clampLateWouldFail;
                worstAffine = std::max(worstAffine, delta(blend(clamped, lambda), expected));
            };
            const double area = cross2(pm.window(t.y) - pm.window(t.x), pm.window(t.z) - pm.window(t.x));
            if (area > -200) continue; // back-facing or a sliver at the rim
            // 3 px margin: deep inside, away from edge rasterization and the neighbouring triangles.
            forEachPixelInside(pm.window(t.x), pm.window(t.y), pm.window(t.z), 3, 256, 256, check);
        }
        std::printf(
            "gouraud/%s: %zu pixels, worst %.4f/255, %zu over 2/255; clamping after interpolation would "
            "be off by > 2/255 at %zu pixels (worst %.1f/255); affine interpolation by up to %.1f/255\n",
            toString(model).data(), pixels, worst, failures, clampLateWouldFail, worstClampLate, worstAffine);
        EXPECT_GT(pixels, 5000u) << "too few pixels inside front-facing triangles";
        EXPECT_EQ(failures, 0u) << "pixels off by more than 2/255; worst " << worst << "/255";
        // The scene must separate clamp-then-interpolate from interpolate-then-clamp (and perspective-correct
        // from affine interpolation), or the test proves nothing.
        EXPECT_GT(clampLateWouldFail, 100u);
        EXPECT_GT(worstAffine, 2.0);
    }
}

struct StiffCase {
    const char* name;
    std::function<void(Scene&)> change;
};

// Test names and failure messages show the case by its name, not as bytes.
inline void PrintTo(const StiffCase& c, std::ostream* os) {
    *os << c.name;
}

const StiffCase kStiffCases[] = {
    {"viewer_opposite_light", // v = −l at the silhouette: the light is straight behind the sphere
     [](Scene& s) {
         s.lights[0].position = {0, 0, -4};
     }},
    {"shininess_1", [](Scene& s) { s.objects[0].material.shininess = 1; }},
    {"shininess_10000", [](Scene& s) { s.objects[0].material.shininess = 1e4; }},
    {"light_inside_sphere",
     [](Scene& s) {
         s.lights[0].position = {0.1, 0.2, 0.1};
     }},
    {"light_on_surface_no_constant_attenuation",
     [](Scene& s) {
         s.lights[0].position = {0, 0, 1};
         s.lights[0].attenuation = {0, 0, 1};
     }},
    {"grazing_directional",
     [](Scene& s) {
         s.lights[0].type = LightType::Directional;
         s.lights[0].direction = {-1, 0, 0};
     }},
    {"very_bright",
     [](Scene& s) {
         s.lights[0].diffuse = s.lights[0].specular = {1e6, 1e6, 1e6};
     }},
    {"spot_cutoff_0_and_90",
     [](Scene& s) {
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

// Mean of (r+g+b)/3 over the pixels interior to the object in both the reference and the rendering (each
// coverage eroded by 2 px, as interiorError does).
double interiorMeanBrightness(const ImageF& image, const ReferenceImage& reference, bool fromReference) {
    const int w = image.width, h = image.height;
    std::vector<int> renderedIds(reference.objectId.size(), -1);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (image.pixel(x, y)[3] > 0.5f)
                renderedIds[std::size_t(y) * w + x] = reference.objectId[std::size_t(y) * w + x];
    const std::vector<bool> inReference = interiorMask(reference.objectId, w, h, 2);
    const std::vector<bool> inRendered = interiorMask(renderedIds, w, h, 2);
    double sum = 0;
    std::size_t n = 0;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const std::size_t i = std::size_t(y) * w + x;
            if (!inReference[i] || !inRendered[i]) continue;
            const float* p = fromReference ? reference.color.pixel(x, y) : image.pixel(x, y);
            sum += (double(p[0]) + p[1] + p[2]) / 3;
            ++n;
        }
    }
    return n ? sum / double(n) : 0;
}

// The float target keeps whatever the shader writes: an 8-bit target would round a value slightly outside
// [0,1] (or a NaN, by the unorm rule) into range and hide it. But the shaders clamp before writing, and GLSL
// leaves min/max with a NaN operand undefined (Mesa returns the other operand, so clamp yields a bound): the
// scan alone checks that the clamp is there, not that the lighting is finite. A NaN or Inf in the lighting
// shows instead as a pixel black (or saturated) where the reference is lit, so the interior's mean brightness
// is compared with the reference's too. Catches: a missing clamp, a NaN or Inf reaching the target, and
// lighting that collapses to black (or white) on a stiff scene: a pow(0, 0), a zero-vector normalize, a
// division by a zero attenuation.
TEST_P(StiffScenes, RenderOnlyFiniteInRangeColoursAsBrightAsTheReference) {
    SHADELAB_REQUIRE_GL(renderer);
    for (ShadingMode mode : kShadingModes) {
        for (LightingModel model : kLightingModels) {
            Scene scene = litSphereScene(96, LightType::Point);
            scene.shading = mode;
            scene.lighting = model;
            scene.objects[0].subdivisions = 6;
            GetParam().change(scene);
            const std::string what = std::string(toString(mode)) + "/" + std::string(toString(model));
            const ImageF image = renderer->renderFloat(scene);
            const ValueScan scan = scanValues(image);
            EXPECT_EQ(scan.nonFinite, 0u) << what;
            EXPECT_EQ(scan.outOfRange, 0u) << what;
            // Where the light does not reach the visible side (light behind, inside or on the sphere) the
            // correct image is ambient only, 0.01, indistinguishable from a NaN clamped to 0 at this
            // tolerance: the 0.05 threshold skips those cases. Elsewhere the interior mean is checked; at
            // level 6 even flat and Gouraud are within 0.02 of the exact mean (toon against the toon
            // reference).
            const ReferenceImage reference = renderReference(scene);
            const double expected = interiorMeanBrightness(image, reference, true);
            const double actual = interiorMeanBrightness(image, reference, false);
            std::printf("%s %s: interior mean brightness %.4f, reference %.4f%s\n", GetParam().name,
                        what.c_str(), actual, expected, expected > 0.05 ? "" : " (not compared: unlit)");
            if (expected > 0.05) {
                EXPECT_NEAR(actual, expected, 0.02) << what;
            }
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Cases, StiffScenes, testing::ValuesIn(kStiffCases),
                         [](const auto& info) { return std::string(info.param.name); });

} // namespace
} // namespace shadelab::test

namespace shadelab::test {
namespace {

// gl/handles.h: a handle made by its constructor owns a new GL object, NoCreate owns none, wrap() adopts
// an id, a move hands the object on, and destruction deletes it (glIs* false afterwards).
TEST(Handles, CreateAdoptMoveAndDelete) {
    SHADELAB_REQUIRE_GL(renderer);
    gl::Id id = 0;
    {
        const gl::Texture texture;
        ASSERT_NE(texture.get(), 0u);
        glBindTexture(GL_TEXTURE_2D, texture.get()); // a name becomes a texture when first bound
        glBindTexture(GL_TEXTURE_2D, 0);
        EXPECT_TRUE(glIsTexture(texture.get()));
        id = texture.get();
    }
    EXPECT_FALSE(glIsTexture(id)) << "a destroyed handle deletes its texture";
    EXPECT_FALSE(gl::Buffer(gl::NoCreate));
    gl::Program program;
    EXPECT_TRUE(glIsProgram(program.get()));
    gl::Program moved = std::move(program);
    EXPECT_FALSE(program); // NOLINT(bugprone-use-after-move): the moved-from state is what is tested
    EXPECT_TRUE(glIsProgram(moved.get()));
    id = moved.get();
    moved = gl::Program(gl::NoCreate);
    EXPECT_FALSE(glIsProgram(id)) << "assigning over a handle deletes what it held";
    gl::Program adopted = gl::Program::wrap(glCreateProgram());
    id = adopted.get();
    EXPECT_TRUE(glIsProgram(id));
    adopted.reset();
    EXPECT_FALSE(glIsProgram(id)) << "an adopted id is deleted by its owner";
    const gl::Shader shader(GL_FRAGMENT_SHADER);
    GLint type = 0;
    glGetShaderiv(shader.get(), GL_SHADER_TYPE, &type);
    EXPECT_EQ(type, GL_FRAGMENT_SHADER);
}

// gl/render_target.h: fit() keeps what it holds at the same size and formats, allocates anew otherwise,
// and after a size the context refuses holds nothing (the error names the size).
TEST(RenderTargets, FitKeepsOrReplacesAndARefusedSizeLeavesNothing) {
    SHADELAB_REQUIRE_GL(renderer);
    gl::RenderTarget target;
    EXPECT_FALSE(target.color());
    target.fit(8, 4, gl::ColorFormat::Rgba8, gl::DepthFormat::Depth24);
    const gl::Id first = target.color().get();
    target.fit(8, 4, gl::ColorFormat::Rgba8, gl::DepthFormat::Depth24);
    EXPECT_EQ(target.color().get(), first) << "the same size and formats: nothing allocated";
    target.fit(8, 4, gl::ColorFormat::Rgba8, gl::DepthFormat::None);
    target.fit(16, 4, gl::ColorFormat::Rgba8, gl::DepthFormat::None);
    EXPECT_EQ(target.width(), 16);
    target.bind();
    glViewport(0, 0, 16, 4);
    glClearColor(1, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    const Image image = target.readRgba8();
    ASSERT_EQ(image.width, 16);
    EXPECT_EQ(image.rgba[0], 255);
    EXPECT_EQ(image.rgba[1], 0);
    try {
        target.fit(1 << 20, 4, gl::ColorFormat::Rgba8, gl::DepthFormat::Depth24);
        ADD_FAILURE() << "a 1048576-pixel-wide target was made";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("1048576x4"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(target.color());
    EXPECT_EQ(target.width(), 0);
    gl::bindDefaultFramebuffer();
}

} // namespace
} // namespace shadelab::test
