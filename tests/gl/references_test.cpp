// Regression images: every shading × lighting variant, and one case per projection, light type and
// transform, rendered at 128×128 and compared with a reference PNG in tests/references/.
// The references are anchored to the equations by analytic_test.cpp (an independent CPU ray-cast), not
// only to themselves. Re-bless with scripts/bless.sh after looking at the new pictures.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>

#include "gl/gl_test_support.h"

namespace shadelab::test {
namespace {

namespace fs = std::filesystem;

const fs::path kReferenceDir = fs::path(SHADELAB_TEST_DATA) / "references";

struct ReferenceCase {
    std::string name;
    std::function<Scene()> scene;
    Tolerance tolerance;
};

// Test names and failure messages show the case by its name, not as bytes.
inline void PrintTo(const ReferenceCase& c, std::ostream* os) {
    *os << c.name;
}

// The tolerances, with their reasons:
// - Same machine kind, same Mesa: llvmpipe is deterministic, so most pixels match exactly. A different
//   CPU gives llvmpipe other SIMD widths and FMA use: ±1/255 per channel from float rounding (maxDelta 1,
//   mean 0.05/255).
// - A pixel centre that lies within float rounding of a triangle edge may flip between two triangles or
//   between object and background: a budget of 24 pixels (of 16384) beyond maxDelta.
constexpr Tolerance kLlvmpipeTolerance{1, 0.05, 24};
// Toon bands and the thresholded highlight are discontinuous: a value within rounding of a band edge
// jumps a whole band (~40/255), so such pixels are budgeted, not the delta loosened.
constexpr Tolerance kToonTolerance{1, 0.3, 64};

// Two lights, a warm point light and a cool directional light, on a level-3 sphere: coarse enough to
// show the facets of flat shading and the polygonal highlight of Gouraud shading.
Scene baseScene() {
    Scene scene = litSphereScene(128, LightType::Point);
    scene.objects[0].subdivisions = 3;
    Light fill;
    fill.type = LightType::Directional;
    fill.direction = {1, 0.5, -0.3};
    fill.diffuse = {0.2, 0.3, 0.6};
    fill.specular = {0.3, 0.3, 0.5};
    scene.lights.push_back(fill);
    return scene;
}

std::vector<ReferenceCase> cases() {
    std::vector<ReferenceCase> out;
    for (ShadingMode mode : kShadingModes) {
        for (LightingModel model : kLightingModels) {
            std::string name = std::string(toString(mode)) + "_" + std::string(toString(model));
            std::replace(name.begin(), name.end(), '-', '_');
            out.push_back({name,
                           [=] {
                               Scene s = baseScene();
                               s.shading = mode;
                               s.lighting = model;
                               return s;
                           },
                           mode == ShadingMode::Toon ? kToonTolerance : kLlvmpipeTolerance});
        }
    }
    auto variant = [&](std::string name, std::function<void(Scene&)> change) {
        out.push_back({std::move(name),
                       [=] {
                           Scene s = baseScene();
                           s.objects[0].subdivisions = 5;
                           change(s);
                           return s;
                       },
                       kLlvmpipeTolerance});
    };
    variant("orthographic",
            [](Scene& s) { s.projection = {ProjectionType::Orthographic, 40, -1.5, 1.5, -1.5, 1.5, 1, 10}; });
    variant("off_centre_frustum",
            [](Scene& s) { s.projection = {ProjectionType::Frustum, 40, -0.1, 0.25, -0.2, 0.1, 0.5, 20}; });
    variant("spot_light", [](Scene& s) { s.lights = litSphereScene(128, LightType::Spot).lights; });
    variant("ellipsoid_mirrored", [](Scene& s) { s.objects[0].scale = {-1.3, 0.7, 0.9}; });
    variant("exact_normals_gouraud", [](Scene& s) {
        s.shading = ShadingMode::Gouraud;
        s.vertexNormals = VertexNormals::Exact;
        s.objects[0].subdivisions = 2;
    });
    variant("eight_lights", [](Scene& s) {
        s.lights.clear();
        for (int i = 0; i < kMaxLights; ++i) {
            Light l;
            l.position = {3 * std::cos(i * 0.785), 3 * std::sin(i * 0.785), 2};
            l.diffuse = {0.15 + 0.1 * (i % 3), 0.15 + 0.1 * ((i + 1) % 3), 0.15 + 0.1 * ((i + 2) % 3)};
            l.specular = l.diffuse;
            s.lights.push_back(l);
        }
    });
    return out;
}

bool blessing() {
    return std::getenv("SHADELAB_BLESS") != nullptr;
}

class References : public testing::TestWithParam<ReferenceCase> {};

TEST_P(References, MatchesReferenceImage) {
    SHADELAB_REQUIRE_GL(renderer);
    const ReferenceCase& c = GetParam();
    const Image actual = renderer->render(c.scene());
    const fs::path expectedPath = kReferenceDir / (c.name + ".png");
    if (blessing()) {
        writePng(actual, expectedPath);
        std::ofstream(kReferenceDir / "RENDERER.txt") << renderer->rendererString() << "\n";
        std::printf("blessed %s\n", expectedPath.c_str());
        return;
    }
    const fs::path failures = fs::current_path() / "reference-failures";
    const std::string stem = std::string(toString(renderer->backend())) + "_" + c.name;
    if (!fs::exists(expectedPath)) { // never created silently: the picture is written to be looked at
        fs::create_directories(failures);
        writePng(actual, failures / (stem + ".actual.png"));
        FAIL() << "missing reference " << expectedPath << "; the render is "
               << (failures / (stem + ".actual.png")) << ": look at it, then run scripts/bless.sh " << c.name;
    }
    const Comparison result = compareImages(actual, readPng(expectedPath), c.tolerance);
    if (!result.passed) {
        fs::create_directories(failures);
        // The references are one driver's pictures: on another, say so (the difference may be the driver's).
        std::string madeWith;
        std::getline(std::ifstream(kReferenceDir / "RENDERER.txt"), madeWith);
        const std::string driverNote = madeWith == renderer->rendererString()
                                           ? ""
                                           : "\n  the references were made with \"" + madeWith +
                                                 "\"; this is \"" + renderer->rendererString() +
                                                 "\": another driver may rasterize differently — look at the "
                                                 "diff, and bless only if the "
                                                 "difference is the driver's (scripts/bless.sh)";
        writePng(actual, failures / (stem + ".actual.png"));
        writePng(diffImage(actual, readPng(expectedPath)), failures / (stem + ".diff.png"));
        ADD_FAILURE() << c.name << ": " << result.summary() << "\n  expected: " << expectedPath
                      << "\n  actual:   " << (failures / (stem + ".actual.png"))
                      << "\n  diff ×8:  " << (failures / (stem + ".diff.png")) << driverNote;
    }
}

INSTANTIATE_TEST_SUITE_P(Cases, References, testing::ValuesIn(cases()),
                         [](const auto& info) { return info.param.name; });

} // namespace
} // namespace shadelab::test
