// Regression images: the scenes in tests/references/*.json rendered at their size (128×128) and compared
// with the PNG beside each.
// The references are anchored to the equations by analytic_test.cpp (an independent CPU ray-cast), not
// only to themselves. Re-bless with scripts/bless.sh after looking at the new pictures.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>

#include "gl/gl_test_support.h"
#include "shadelab/image/image_file.h"
#include "shadelab/scene/scene_file.h"
#include "tolerances.h"

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

// The tolerances, with their reasons: kRegressionTolerance (tolerances.h) for every case but toon's.
// Toon bands and the thresholded highlight are discontinuous: a value within rounding of a band edge
// jumps a whole band (~40/255), so such pixels are budgeted, not the delta loosened.
constexpr Tolerance kToonTolerance{1, 0.3, 64};

// The cases are the scenes in tests/references/*.json, each beside its PNG: adding a case is adding a scene
// file and blessing its picture, with no rebuild (the folder is read each run; ctest's per-case names are
// those of the last build, and ReferenceFiles.EverySceneMatchesItsPicture covers files added since). Toon
// scenes take the toon tolerance, all others the llvmpipe one. The set: every shading ×
// lighting variant of a level-3 sphere under a warm point light and a cool directional fill light, and at
// level 5 one case per projection, light type, transform, normal kind and the eight-light maximum.
std::vector<ReferenceCase> cases() {
    std::vector<ReferenceCase> out;
    for (const auto& entry : fs::directory_iterator(kReferenceDir)) {
        if (entry.path().extension() != ".json") continue;
        const Scene scene = loadScene(entry.path());
        out.push_back({entry.path().stem().string(), [scene] { return scene; },
                       scene.shading == ShadingMode::Toon ? kToonTolerance : kRegressionTolerance});
    }
    std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
    return out;
}

bool blessing() {
    return std::getenv("SHADELAB_BLESS") != nullptr;
}

class References : public testing::TestWithParam<ReferenceCase> {};

void checkReference(HeadlessRenderer* renderer, const ReferenceCase& c) {
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

TEST_P(References, MatchesReferenceImage) {
    SHADELAB_REQUIRE_GL(renderer);
    checkReference(renderer, GetParam());
}

// The folder as it is now, whatever the last build listed: a scene file added since is checked too.
TEST(ReferenceFiles, EverySceneMatchesItsPicture) {
    SHADELAB_REQUIRE_GL(renderer);
    for (const ReferenceCase& c : cases()) {
        SCOPED_TRACE(c.name);
        checkReference(renderer, c);
    }
}

// Every picture has its scene and every scene its picture (a scene without one fails in the test above).
TEST(ReferenceFiles, EveryPngHasItsSceneJson) {
    std::size_t pictures = 0;
    for (const auto& entry : fs::directory_iterator(kReferenceDir)) {
        if (entry.path().extension() != ".png") continue;
        ++pictures;
        fs::path scene = entry.path();
        scene.replace_extension(".json");
        EXPECT_TRUE(fs::exists(scene)) << entry.path().filename() << " has no " << scene.filename();
    }
    EXPECT_GE(pictures, 14u);
}

INSTANTIATE_TEST_SUITE_P(Cases, References, testing::ValuesIn(cases()),
                         [](const auto& info) { return info.param.name; });

} // namespace
} // namespace shadelab::test
