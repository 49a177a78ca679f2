// Extreme geometry and transforms (gl/extreme_support.h): near-singular, mirrored and huge scales, radii
// from 1e-6 to 1e6, a sphere far from the origin, and the subdivision levels at and beyond the maximum.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "gl/allocation_watch.h"
#include "gl/extreme_support.h"
#include "input_error.h"
#include "shadelab/errors.h"
#include "shadelab/scene/auto_level.h"

namespace shadelab::test {
namespace {

struct ScaleCase {
    const char* name;
    glm::dvec3 scale;
    glm::dvec3 eye;
    DepthMode depth = DepthMode::Standard;
    double near = 0.5, far = 20;
    double averagedMax = 4; // max interior error allowed with the seed's averaged vertex normals (1/255)
};

// Non-uniform, near-singular and mirrored scales. Normals come from the cofactor matrix (DESIGN §2), which
// never divides: a 1e-6 axis must give a plate lit as a plate, a 1e6 axis a cylinder lit as a cylinder, and
// a mirror must keep normals outward. Expected: finite, and Phong at level 8 within its limits of the
// reference on the interior (mean < 0.5/255, max <= 4/255), with both kinds of vertex normal. With exact
// normals the mesh's own normal error is gone, so what remains is the transform's.
//
// The disc and plate are 2e-6 thick: their two faces are 2e-6 apart at distance ≈ 4, which standard depth
// with near 0.5 cannot separate (DESIGN §2: ≈ 6e-8·d²/near ≈ 1.9e-6; measured, the back face shows through:
// interior mean 27–39/255, with exact normals too). That is depth precision, not normals, so they are drawn
// with reversed-Z (≈ 1.2e-7·d ≈ 5e-7) or with near/far hugging the object (≈ 6e-8·16/3 ≈ 3e-7).
const ScaleCase kScaleCases[] = {
    {"thin_disc_facing_camera_reversed_z", {1, 1, 1e-6}, {0, 0, 4}, DepthMode::Reversed},
    {"thin_disc_facing_camera_near_3_far_5", {1, 1, 1e-6}, {0, 0, 4}, DepthMode::Standard, 3, 5},
    {"thin_plate_seen_obliquely_reversed_z", {1, 1e-6, 1}, {0, 2.5, 3}, DepthMode::Reversed},
    // Seen across, the ellipsoid shows the great circle x = 0 of the unit mesh in every one of its 128
    // columns — and that circle holds the start tetrahedron's edge a–b, along which the averaged normals are
    // at their worst (up to 2.7e-3 rad at level 8). A sphere shows that edge in a few pixels; here it is a
    // whole row, and the Phong highlight crosses it: measured max 4.9/255 with averaged normals, 0.01/255
    // with exact ones. Allowed: 6/255 with averaged normals.
    {"long_cigar_across_view", {1e6, 1, 1}, {0, 0, 4}, DepthMode::Standard, 0.5, 20, 6},
    {"long_cigar_obliquely", {1, 1e6, 1}, {1.5, 0, 3.5}},
    {"mirrored_x", {-1.3, 0.7, 0.9}, {0, 0, 4}},
    {"mirrored_xyz", {-1.3, -0.7, -0.9}, {0, 0, 4}},
};

void PrintTo(const ScaleCase& c, std::ostream* os) {
    *os << c.name;
}

class ExtremeScale : public testing::TestWithParam<ScaleCase> {};

TEST_P(ExtremeScale, FiniteAndMatchesTheReferenceOnTheInterior) {
    SHADELAB_REQUIRE_GL(renderer);
    const ScaleCase& param = GetParam();
    Scene scene = phongScene(128);
    scene.objects[0].scale = param.scale;
    scene.eye = param.eye;
    scene.depth = param.depth;
    scene.projection.near = param.near;
    scene.projection.far = param.far;
    for (VertexNormals normals : {VertexNormals::Exact, VertexNormals::Averaged}) {
        for (LightingModel model : kLightingModels) {
            scene.vertexNormals = normals;
            scene.lighting = model;
            const std::string what = std::string(param.name) + "/" + std::string(toString(model)) + "/" +
                                     std::string(normalsName(normals));
            const ImageF image = checkedRender(*renderer, scene, what);
            const ReferenceImage reference = checkedReference(scene, what);
            if (normals == VertexNormals::Exact) {
                expectPhongLimits(image, reference, what, 1000);
            } else {
                const InteriorError e = interiorError(image, reference);
                std::printf("  %s: interior mean %.3f/255, max %.3f/255 over %zu pixels\n", what.c_str(),
                            e.mean, e.max, e.pixels);
                EXPECT_GE(e.pixels, 1000u) << what;
                EXPECT_LT(e.mean, 0.5) << what;
                EXPECT_LE(e.max, param.averagedMax) << what;
            }
            // The sign of the normal matrix is shared with the reference (both use normalMatrix), so a
            // mirrored scale is also compared with its unmirrored twin: a mirrored ellipsoid centred at the
            // origin is the same surface; only the mesh (and so a few silhouette pixels) differs.
            const glm::dvec3 s = param.scale;
            if (s.x < 0 || s.y < 0 || s.z < 0) {
                Scene twin = scene;
                twin.objects[0].scale = glm::abs(s);
                expectSameImage(image, checkedRender(*renderer, twin, what + " unmirrored"),
                                what + " vs unmirrored");
            }
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Cases, ExtremeScale, testing::ValuesIn(kScaleCases),
                         [](const auto& info) { return std::string(info.param.name); });

// A disc 1e-6 thick seen exactly edge-on is thinner than a pixel everywhere: no interior to compare.
// Expected: finite, and the covered area that of the reference within one pixel column (a pixel is covered
// only where its centre falls within the 4e-5-pixel-wide disc, which the rasterizer's sub-pixel grid cannot
// resolve), never a smear.
TEST(ExtremeScaleEdgeOn, ThinDiscEdgeOnIsFiniteWithTheReferencesArea) {
    SHADELAB_REQUIRE_GL(renderer);
    for (int size : {128, 129}) { // 129: the middle column of pixel centres lies exactly in the disc's plane
        Scene scene = phongScene(size);
        scene.objects[0].scale = {1e-6, 1, 1};
        const std::string what = "edge-on disc " + std::to_string(size) + "px";
        const ImageF image = checkedRender(*renderer, scene, what);
        const ReferenceImage reference = checkedReference(scene, what);
        const std::size_t covered = coveredPixels(image), expected = coveredPixels(reference);
        std::printf("  %s: %zu pixels covered, reference %zu\n", what.c_str(), covered, expected);
        EXPECT_LE(std::max(covered, expected) - std::min(covered, expected), std::size_t(size)) << what;
    }
}

// Radii 1e-6 .. 1e6 with the whole scene scaled to match (eye, light, near, far, and the attenuation
// coefficients b/r and c/r² so that att is unchanged). Expected: the image of the unit scene within the
// regression tolerance — float positions and the normal matrix are relative to the object's scale.
TEST(ExtremeRadius, ScaledSceneMatchesTheUnitScene) {
    SHADELAB_REQUIRE_GL(renderer);
    auto scaled = [](double r) {
        Scene scene = scaledSphereScene(128, r);
        scene.objects[0].subdivisions = 6;
        return scene;
    };
    for (ShadingMode mode : {ShadingMode::Phong, ShadingMode::Gouraud}) {
        for (LightingModel model : kLightingModels) {
            Scene unit = scaled(1);
            unit.shading = mode;
            unit.lighting = model;
            const std::string how = std::string(toString(mode)) + "/" + std::string(toString(model));
            const ImageF expected = checkedRender(*renderer, unit, "unit " + how);
            for (double r : {1e-6, 1e-3, 1e3, 1e6}) {
                Scene scene = scaled(r);
                scene.shading = mode;
                scene.lighting = model;
                char what[64];
                std::snprintf(what, sizeof what, "radius %g %s", r, how.c_str());
                expectSameImage(checkedRender(*renderer, scene, what), expected, what);
            }
        }
    }
}

// A sphere 1e6 from the origin with the camera and light beside it (eye = centre + (0,0,4)). In float the
// world coordinates would be quantized to 1/16; view·model composed in double (DESIGN §2) leaves only
// camera-relative values. Expected: the image of the same scene at the origin within the regression
// tolerance, and the reference's interior limits.
TEST(FarFromOrigin, MatchesTheSameSceneAtTheOrigin) {
    SHADELAB_REQUIRE_GL(renderer);
    const Scene atOrigin = phongScene(128);
    const ImageF expected = checkedRender(*renderer, atOrigin, "at the origin");
    for (const glm::dvec3& centre :
         {glm::dvec3(1e6, 0, 0), glm::dvec3(0, 0, -1e6), glm::dvec3(1, -1, 1) * (1e6 / std::sqrt(3.0))}) {
        Scene scene = atOrigin;
        scene.objects[0].center = centre;
        scene.eye = centre + glm::dvec3(0, 0, 4);
        scene.target = centre;
        scene.lights[0].position += centre;
        char what[96];
        std::snprintf(what, sizeof what, "centre (%g, %g, %g)", centre.x, centre.y, centre.z);
        const ImageF image = checkedRender(*renderer, scene, what);
        expectSameImage(image, expected, what);
        expectPhongLimits(image, checkedReference(scene, what), what, 1000);
    }
}

// One above the highest level is refused before anything is built: validateScene names the field and the
// memory the level would need, and so does the renderer, with no large allocation on the way.
TEST(Subdivision, LevelAboveTheMaximumIsAnInputErrorNamingTheMemoryWithoutAllocating) {
    SHADELAB_REQUIRE_GL(renderer);
    Scene scene = phongScene(64);
    (void)checkedRender(*renderer, scene, "warm-up"); // context, programs and the level-8 mesh exist
    scene.objects[0].subdivisions = kMaxSubdivisions + 1;

    resetLargestAllocation();
    const std::string validated = inputErrorOf([&] { validateScene(scene); });
    const std::size_t validateLargest = largestAllocation();
    resetLargestAllocation();
    const std::string rendered = inputErrorOf([&] { (void)renderer->renderFloat(scene); });
    const std::size_t renderLargest = largestAllocation();
    std::printf(
        "  validateScene: \"%s\" (largest allocation %zu B)\n  render: \"%s\" (largest allocation %zu "
        "B); level %d needs %zu B\n",
        validated.c_str(), validateLargest, rendered.c_str(), renderLargest, kMaxSubdivisions + 1,
        sphereMemoryBytes(kMaxSubdivisions + 1));
    EXPECT_NE(validated.find("objects[0].subdivisions"), std::string::npos) << validated;
    for (const std::string& message : {validated, rendered}) {
        EXPECT_NE(message.find("subdivisions"), std::string::npos) << message;
        EXPECT_NE(message.find("would need"), std::string::npos) << message;
        EXPECT_NE(message.find("GiB"), std::string::npos) << message;
    }
    // The level would take gigabytes; a refusal that started building it would ask for hundreds of MiB.
    // (The watch does see a mesh being built: level 7 reserves its 32770 positions in one piece.)
    resetLargestAllocation();
    (void)buildSphere(7);
    EXPECT_GE(largestAllocation(), sphereVertexCount(7) * sizeof(glm::dvec3));
    EXPECT_LT(validateLargest, std::size_t(1) << 20);
    EXPECT_LT(renderLargest, std::size_t(1) << 20);
    // And the renderer is still usable.
    scene.objects[0].subdivisions = 8;
    expectSameImage(checkedRender(*renderer, scene, "after the refusal"),
                    checkedRender(*renderer, phongScene(64), "level 8"), "after the refusal");
}

// The highest supported level (kMaxSubdivisions = 10, 4.2M triangles) renders, correctly: finite and within
// the Phong limits of the reference. 64×64 is enough; the time is printed.
TEST(Subdivision, HighestLevelRenders) {
    SHADELAB_REQUIRE_GL(renderer);
    Scene scene = phongScene(64);
    scene.objects[0].subdivisions = kMaxSubdivisions;
    const auto start = std::chrono::steady_clock::now();
    const ImageF image = checkedRender(*renderer, scene, "level 10");
    const double first = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const auto again = std::chrono::steady_clock::now();
    (void)checkedRender(*renderer, scene, "level 10 again");
    const double second = std::chrono::duration<double>(std::chrono::steady_clock::now() - again).count();
    std::printf("  level %d: %zu triangles, first render (build + upload + draw) %.2f s, cached %.2f s\n",
                kMaxSubdivisions, sphereTriangleCount(kMaxSubdivisions), first, second);
    expectPhongLimits(image, checkedReference(scene, "level 10"), "level 10");
}

} // namespace
} // namespace shadelab::test
