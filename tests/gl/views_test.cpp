// The teaching views (src/gl/views.h) against their parts: the error view's figures against
// `shadelab report`'s measure of the same configuration, the split view's halves against plain renders of
// its sides, the profile's samples against the rendered rows.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "app/report/report.h"
#include <glm/gtc/matrix_transform.hpp>

#include "gl/gl_test_support.h"
#include "gl/views.h" // private (src/gl/): splitSideScene, profileRow
#include "shadelab/diagram/outside_view.h"
#include "shadelab/image/image_file.h"

namespace shadelab::test {
namespace {

Scene sphereAt(ShadingMode mode, int level, int size = 256) {
    Scene scene = litSphereScene(size, LightType::Point);
    scene.shading = mode;
    scene.objects[0].subdivisions = level;
    return scene;
}

View viewOf(std::string_view text) {
    const ViewParse parsed = parseView(text);
    EXPECT_TRUE(parsed.view.has_value()) << parsed.error;
    return parsed.view.value_or(View{});
}

// The issue's bar: the error view's interior mean (computed on the GPU against exact shading) agrees with
// report's interior_mean_error (the float render against the CPU reference) within 0.05/255. Both count
// the same interior (measured: the same pixels to the last one) and exact shading is the reference within
// 0.003/255, so what is left is float summation on the GPU. Toon is measured against the quantized exact
// sphere in both.
TEST(ErrorView, FiguresAgreeWithReportsMeasure) {
    SHADELAB_REQUIRE_GL(renderer);
    struct Config {
        ShadingMode mode;
        int level;
    };
    for (const Config& c :
         {Config{ShadingMode::Flat, 2}, Config{ShadingMode::Flat, 5}, Config{ShadingMode::Gouraud, 3},
          Config{ShadingMode::Gouraud, 6}, Config{ShadingMode::Phong, 4}, Config{ShadingMode::Phong, 7},
          Config{ShadingMode::Toon, 5}}) {
        for (LightingModel model : kLightingModels) {
            Scene scene = sphereAt(c.mode, c.level);
            scene.lighting = model;
            const std::string what = std::string(toString(c.mode)) + "@" + std::to_string(c.level) + "/" +
                                     std::string(toString(model));
            const app::ReportError report =
                app::measureError(renderer->renderFloat(scene), renderReference(scene));
            Scene errorView = scene;
            errorView.view = viewOf("error");
            const Image picture = renderer->render(errorView);
            const gl::ViewFigures& f = renderer->viewFigures();
            std::printf("  %s: view mean %.4f max %.3f over %zu px; report mean %.4f max %.3f over %zu px\n",
                        what.c_str(), f.interiorMean, f.interiorMax, f.interiorPixels, report.interiorMean,
                        report.interiorMax, report.interiorPixels);
            EXPECT_NEAR(f.interiorMean, report.interiorMean, 0.05) << what;
            EXPECT_NEAR(f.interiorMax, report.interiorMax, 0.05) << what;
            EXPECT_EQ(f.interiorPixels, report.interiorPixels) << what;
            EXPECT_GE(f.scale, f.interiorMax) << what << ": the legend's top is below the largest error";
            EXPECT_EQ(picture.width, scene.width);
        }
    }
}

// Exact against exact: the view measures nothing (float rounding only), so a wrong pairing of the two
// renders (e.g. both the mode) would not go unnoticed in the test above either way.
TEST(ErrorView, ExactShadingShowsNoError) {
    SHADELAB_REQUIRE_GL(renderer);
    Scene scene = sphereAt(ShadingMode::Exact, 0);
    scene.view = viewOf("error");
    renderer->render(scene);
    EXPECT_LT(renderer->viewFigures().interiorMax, 0.01);
    EXPECT_GT(renderer->viewFigures().interiorPixels, 10000u);
}

// Where neither render covers a pixel the heatmap leaves the background; inside, it is the colour map
// (never the shaded sphere): the sphere's centre pixel of a level-6 Phong render is viridis' dark end.
TEST(ErrorView, HeatmapKeepsTheBackgroundAndColoursTheObject) {
    SHADELAB_REQUIRE_GL(renderer);
    Scene scene = sphereAt(ShadingMode::Phong, 6);
    scene.background = {0.2, 0.3, 0.4};
    scene.view = viewOf("error");
    const Image picture = renderer->render(scene);
    const std::uint8_t* corner = picture.pixel(100, 250); // below the sphere, left of the legend
    EXPECT_NEAR(corner[0], 0.2 * 255, 1);                 // rounding to 8 bits differs between drivers by one
    EXPECT_NEAR(corner[1], 0.3 * 255, 1);
    EXPECT_NEAR(corner[2], 0.4 * 255, 1);
    const std::uint8_t* centre = picture.pixel(128, 140);
    EXPECT_NEAR(centre[0], 68, 8); // viridis(0) = (0.267, 0.005, 0.329): error ≪ the scale
    EXPECT_LT(centre[1], 30);
    EXPECT_NEAR(centre[2], 84, 10);
}

// Whether pixel (x, y) lies in one of a view's label boxes (ViewFigures::labels).
bool inLabel(const std::vector<gl::ViewFigures::LabelBox>& labels, int x, int y) {
    for (const gl::ViewFigures::LabelBox& box : labels)
        if (box.overlaps({x, y, 1, 1})) return true;
    return false;
}

// Each half of a split view is a plain render of its side on its pixels (away from the divider's two columns
// and the labels' row).
TEST(SplitView, EachHalfIsAPlainRenderOfItsSide) {
    SHADELAB_REQUIRE_GL(renderer);
    for (const char* text :
         {"split:gouraud,phong", "split:phong@2,phong@6", "split:phong,blinn-phong", "split:flat,exact",
          "split:scene,outside", "split:gouraud,ndc", "split:phong{shininess=8},phong{shininess=150}",
          "split:{term=diffuse},{term=specular}", "split:gouraud{diffuse=0.2 0.6 0.9,ambient=0},gouraud"}) {
        for (double at : {0.5, 0.3}) {
            Scene scene = sphereAt(ShadingMode::Phong, 4);
            scene.view = viewOf(text);
            scene.view.at = at;
            const Image split = renderer->render(scene);
            const std::vector<gl::ViewFigures::LabelBox> labels = renderer->viewFigures().labels;
            const Image left = renderer->render(gl::splitSideScene(scene, scene.view.left));
            const Image right = renderer->render(gl::splitSideScene(scene, scene.view.right));
            const int divider = int(std::lround(at * scene.width));
            ASSERT_EQ(labels.size(), 2u);
            EXPECT_FALSE(labels[0].overlaps(labels[1])) << "the two sides' labels overlap";
            std::size_t leftDiffers = 0, rightDiffers = 0, leftFromRight = 0;
            for (int y = 0; y < scene.height; ++y)
                for (int x = 0; x < scene.width; ++x) {
                    if (std::abs(x - divider) <= 1 || inLabel(labels, x, y)) continue;
                    const Image& expected = x < divider ? left : right;
                    bool differs = false;
                    for (int c = 0; c < 4; ++c) differs |= split.pixel(x, y)[c] != expected.pixel(x, y)[c];
                    (x < divider ? leftDiffers : rightDiffers) += differs;
                    for (int c = 0; c < 3; ++c) leftFromRight += left.pixel(x, y)[c] != right.pixel(x, y)[c];
                }
            SCOPED_TRACE(std::string(text) + " at " + std::to_string(at));
            EXPECT_EQ(leftDiffers, 0u);
            EXPECT_EQ(rightDiffers, 0u);
            EXPECT_GT(leftFromRight, 100u) << "the two sides draw the same picture";
            // The divider is white.
            const std::uint8_t* line = split.pixel(divider, scene.height - 5);
            EXPECT_EQ(line[0], 255);
            EXPECT_EQ(line[1], 255);
            EXPECT_EQ(line[2], 255);
        }
    }
}

// Side by side, each side is the whole picture in its half: the camera's view of the full width in half the
// pixels, so two spheres far apart both show whole in each half (nothing at a half's edges), and each half
// is, pixel for pixel, the render of its side at that size with the view volume made as much taller
// (written out here: fovy from tan(fovy/2)·2).
TEST(SplitView, SideBySideShowsEachSideWholeInItsHalf) {
    SHADELAB_REQUIRE_GL(renderer);
    Scene scene = sphereAt(ShadingMode::Phong, 4);
    scene.width = 320;
    scene.height = 160;
    scene.objects.push_back(scene.objects[0]);
    scene.objects[0].center = {-1.3, 0, 0};
    scene.objects[1].center = {1.3, 0, 0};
    scene.view = viewOf("side-by-side:phong{shininess=8},phong{shininess=150}");
    const Image picture = renderer->render(scene);
    const std::vector<gl::ViewFigures::LabelBox> labels = renderer->viewFigures().labels;
    const int half = scene.width / 2;
    for (const auto& [side, x0] : {std::pair{scene.view.left, 0}, std::pair{scene.view.right, half}}) {
        Scene expected = gl::splitSideScene(scene, side);
        expected.width = half;
        expected.projection.fovyDeg =
            glm::degrees(2 * std::atan(2 * std::tan(glm::radians(scene.projection.fovyDeg) / 2)));
        const Image alone = renderer->render(expected);
        std::size_t differs = 0, atTheEdges = 0;
        int largest = 0;
        for (int y = 0; y < scene.height; ++y)
            for (int x = 0; x < half; ++x) {
                if (std::abs(x0 + x - half) <= 1 || inLabel(labels, x0 + x, y)) continue;
                for (int c = 0; c < 3; ++c) {
                    const int d = std::abs(int(picture.pixel(x0 + x, y)[c]) - int(alone.pixel(x, y)[c]));
                    largest = std::max(largest, d);
                    differs += d != 0;
                }
                if (x == 2 || x == half - 3)
                    for (int c = 0; c < 3; ++c) atTheEdges += picture.pixel(x0 + x, y)[c] != 0;
            }
        SCOPED_TRACE(toString(side));
        // The right half's viewport starts at x = half, the render alone at 0: the same triangles in window
        // coordinates shifted by a whole number, which the rasterizer's float-to-fixed conversion can still
        // round differently at a pixel (measured: one channel of one pixel, by 1/255, on llvmpipe).
        EXPECT_LE(largest, 1) << "the half is its side's render at half the width, the volume twice as tall";
        EXPECT_LE(differs, 8u);
        EXPECT_EQ(atTheEdges, 0u) << "an object is cut at the half's edge";
    }
    // The sides' settings show: the wide highlight (shininess 8) lights more of the left half than the sharp
    // one (150) does of the right.
    std::size_t brightLeft = 0, brightRight = 0;
    for (int y = 0; y < scene.height; ++y)
        for (int x = 0; x < half; ++x) {
            brightLeft += !inLabel(labels, x, y) && picture.pixel(x, y)[1] > 200;
            brightRight += !inLabel(labels, half + x, y) && picture.pixel(half + x, y)[1] > 200;
        }
    EXPECT_GT(brightLeft, 4 * brightRight + 20);
}

// The profile's samples are the rows of the mode's and exact's renders; the picture away from the plot and
// the row's marker is the plain render; mesh edges cross the row more often at a finer level.
TEST(ProfileView, SamplesAreTheRenderedRowsAndEdgesFollowTheLevel) {
    SHADELAB_REQUIRE_GL(renderer);
    std::size_t previousEdges = 0;
    for (int level : {2, 4}) {
        for (ShadingMode mode : {ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong}) {
            Scene scene = sphereAt(mode, level);
            scene.view = viewOf("profile");
            const Image picture = renderer->render(scene);
            const gl::ViewFigures f = renderer->viewFigures();
            Scene plain = scene;
            plain.view = View{};
            const ImageF modeImage = renderer->renderFloat(plain);
            plain.shading = ShadingMode::Exact;
            const ImageF exactImage = renderer->renderFloat(plain);
            const std::string what = std::string(toString(mode)) + "@" + std::to_string(level);
            ASSERT_EQ(f.row, scene.height / 2) << what << ": the row through the sphere's centre";
            ASSERT_EQ(f.modeRow.size(), std::size_t(scene.width));
            for (int x = 0; x < scene.width; ++x) {
                const float* m = modeImage.pixel(x, f.row);
                const float* e = exactImage.pixel(x, f.row);
                ASSERT_EQ(f.modeRow[std::size_t(x)], (m[0] + m[1] + m[2]) / 3) << what << " column " << x;
                ASSERT_EQ(f.exactRow[std::size_t(x)], (e[0] + e[1] + e[2]) / 3) << what << " column " << x;
            }
            if (mode == ShadingMode::Flat) {
                std::printf("  level %d: %zu edge crossings on row %d\n", level, f.edgeColumns.size(), f.row);
                EXPECT_GT(f.edgeColumns.size(), previousEdges) << what;
                previousEdges = f.edgeColumns.size();
            }
            // The row is in the middle: the plot covers the top third; below it the plain picture, except
            // the marker's row.
            plain.shading = mode;
            const Image expected = renderer->render(plain);
            std::size_t differs = 0;
            for (int y = scene.height / 3 + 1; y < scene.height; ++y)
                for (int x = 0; x < scene.width; ++x)
                    if (y != f.row)
                        for (int c = 0; c < 4; ++c)
                            differs += picture.pixel(x, y)[c] != expected.pixel(x, y)[c];
            EXPECT_EQ(differs, 0u) << what;
        }
    }
}

// Headless: the row through the first object's centre, or view_at of the height.
TEST(ProfileView, RowIsTheFirstObjectsCentreOrViewAt) {
    Scene scene = sphereAt(ShadingMode::Phong, 3, 200);
    EXPECT_EQ(gl::profileRow(scene, 200), 100);
    scene.objects[0].center = {0, 0.5, 0}; // above the axis: a row nearer the top
    EXPECT_LT(gl::profileRow(scene, 200), 90);
    scene.view.at = 0.25;
    EXPECT_EQ(gl::profileRow(scene, 200), 50);
}

// The outside view: the view volume's corners, computed independently, are drawn where the observer's
// camera puts them, for each projection, the unnegated matrix and an orbited observer.
Scene volumeOnlyScene() {
    Scene scene;
    scene.width = scene.height = 256;
    scene.eye = {0, 0, 5};
    scene.projection = {ProjectionType::Perspective, 50, -1, 1, -1, 1, 2.5, 7};
    scene.objects.clear(); // the lines alone: nothing hides a corner
    scene.lights.clear();
    scene.view.kind = ViewKind::Outside;
    return scene;
}

std::string joined(const std::vector<std::string>& lines) {
    std::string text;
    for (const std::string& line : lines) text += line + "\n";
    return text;
}

TEST(OutsideView, ViewVolumeCornersLandOnTheDrawnCorners) {
    SHADELAB_REQUIRE_GL(renderer);
    std::vector<std::pair<std::string, Scene>> cases;
    cases.emplace_back("perspective", volumeOnlyScene());
    Scene frustum = volumeOnlyScene();
    frustum.projection = {ProjectionType::Frustum, 40, -1.4, 0.6, -0.8, 1.2, 2, 6};
    cases.emplace_back("off-centre frustum", frustum);
    Scene box = volumeOnlyScene();
    box.projection = {ProjectionType::Orthographic, 40, -1.5, 1.5, -1, 1.2, 1, 6};
    cases.emplace_back("orthographic", box);
    Scene orbited = volumeOnlyScene();
    orbited.view.observer = {-40, -15, 1.2};
    orbited.eye = {2, 1, 4};
    cases.emplace_back("orbited observer, off-axis eye", orbited);
    Scene unnegated = volumeOnlyScene();
    unnegated.perspectiveMatrix = PerspectiveMatrix::Unnegated;
    cases.emplace_back("unnegated", unnegated);
    for (const auto& [name, scene] : cases) {
        SCOPED_TRACE(name);
        const Image image = renderer->render(scene);
        const std::vector<std::string> misses = outsideCornerMisses(image, scene);
        EXPECT_TRUE(misses.empty()) << joined(misses);
        if (!misses.empty()) writePng(image, "outside_view_failed.png"); // to look at
    }
    // The check can fail: a picture of a volume whose near plane is 0.3 farther has its near corners
    // elsewhere.
    Scene moved = volumeOnlyScene();
    moved.projection.near = 2.8;
    EXPECT_FALSE(outsideCornerMisses(renderer->render(moved), volumeOnlyScene()).empty());
}

// The picture carries the view's title alone: how to move the observer ("drag: orbit, wheel: zoom") is said
// in the window's title and status line, which a pointer reaches, and never in a PNG or a slide. The title's
// box, down the column of its left padding, is one text line and its padding high (11 + 6 rows per scale).
TEST(OutsideView, TheTitleIsOneLineWithoutInteractionHints) {
    SHADELAB_REQUIRE_GL(renderer);
    for (const ViewKind kind : {ViewKind::Outside, ViewKind::Ndc}) {
        Scene scene = volumeOnlyScene();
        scene.view.kind = kind;
        scene.background = {0.5, 0.5, 0.5}; // the translucent black box shows on it
        const Image picture = renderer->render(scene);
        const int scale = 1; // text scale 1 below a 400-pixel picture (256 x 256 here)
        const int x = 4 * scale + 1, top = 4 * scale;
        auto rgb = [&](int y) {
            return glm::u8vec3(picture.pixel(x, y)[0], picture.pixel(x, y)[1], picture.pixel(x, y)[2]);
        };
        const glm::u8vec3 background = rgb(top - 2), box = rgb(top + 1);
        ASSERT_NE(box, background) << toString(scene.view) << ": the title's box is drawn at (4, 4) x scale";
        int rows = 0;
        while (top + rows < scene.height && rgb(top + rows) == box) ++rows;
        EXPECT_EQ(rows, (11 + 6) * scale) << toString(scene.view) << ": one line of text in the title's box";
    }
}

TEST(OutsideView, ObjectsAreDrawnAsTheObserverSeesThemUnderTheTranslucentFaces) {
    SHADELAB_REQUIRE_GL(renderer);
    Scene scene = volumeOnlyScene();
    scene.objects = {SceneObject{}};
    scene.lights = {Scene::defaultLight()};
    const Image outside = renderer->render(scene);
    const std::vector<gl::ViewFigures::LabelBox> labels = renderer->viewFigures().labels;
    // The observer's own render of the objects: wherever it covers a pixel, the outside view shows that
    // pixel, or it under the near or far face (blended with alpha kFaceAlpha, either or both), or a line.
    const Image plain = renderer->render(observerScene(scene));
    auto blend = [](glm::vec3 under, glm::vec3 face) { return (1 - kFaceAlpha) * under + kFaceAlpha * face; };
    std::size_t covered = 0, explained = 0;
    for (std::size_t k = 0; k < plain.rgba.size(); k += 4) {
        const int pixel = int(k / 4);
        if (plain.rgba[k + 3] == 0 || inLabel(labels, pixel % scene.width, pixel / scene.width)) continue;
        ++covered;
        const glm::vec3 p = glm::vec3(plain.rgba[k], plain.rgba[k + 1], plain.rgba[k + 2]) / 255.0f;
        const glm::vec3 o = glm::vec3(outside.rgba[k], outside.rgba[k + 1], outside.rgba[k + 2]) / 255.0f;
        bool found = false;
        for (const glm::vec3& under :
             {p, blend(p, kNearFaceColor), blend(p, kFarFaceColor),
              blend(blend(p, kFarFaceColor), kNearFaceColor), blend(blend(p, kNearFaceColor), kFarFaceColor),
              kVolumeEdgeColor, 0.5f * kVolumeEdgeColor})
            found |= glm::all(glm::lessThanEqual(glm::abs(o - under), glm::vec3(2.5f / 255)));
        explained += found;
    }
    EXPECT_GT(covered, 500u) << "the observer sees the sphere";
    EXPECT_GT(double(explained), 0.97 * double(covered))
        << explained << " of " << covered << " sphere pixels";
    // And the sphere does hide what is behind it: the view without the sphere differs there.
    Scene empty = scene;
    empty.objects.clear();
    EXPECT_NE(renderer->render(empty).rgba, outside.rgba);
}

// Which of the cube's bounds the analytic image clips a hit to: all of |x|, |y|, |z| <= 1 (the clipper's
// test), or only |x| and |y| (what the picture would show if the NDC view forgot to clip in z).
enum class NdcClip { Cube, XyOnly };

// Pixels of an NDC view picture of one flat red unit sphere where the sphere drawn and its analytic image
// under `analytic`'s M_proj·M_cam disagree, 2 px or more from the analytic silhouette (the level-7 mesh
// lies within 0.02 px of it); `inside` counts the analytic sphere's pixels compared. Each pixel's ray from
// the observer, a line in NDC, is a line in world space too (a projective map keeps lines): taken back
// through inverse(M_proj·M_cam), intersected with the exact sphere, a hit counts if it lies in the cube
// (or its xy-slab, `clip`) and in front of the observer. Both roots are tried: where the near or far plane
// cuts the sphere, the observer sees its inside through the cut.
std::size_t ndcMismatches(const Image& image, const Scene& analytic, std::size_t& inside,
                          NdcClip clip = NdcClip::Cube,
                          const std::vector<gl::ViewFigures::LabelBox>& labels = {}) {
    const glm::dmat4 cameraClipFromWorld =
        webGlClipFromView(analytic) * glm::lookAt(analytic.eye, analytic.target, analytic.up);
    const glm::dmat4 worldFromNdc = glm::inverse(cameraClipFromWorld);
    const Scene observer = ndcObserverScene(analytic);
    const glm::dmat4 observerClipFromNdc =
        webGlClipFromView(observer) * glm::lookAt(observer.eye, observer.target, observer.up);
    const glm::dmat4 ndcFromObserverClip = glm::inverse(observerClipFromNdc);
    auto dehomogenize = [](const glm::dvec4& p) { return glm::dvec3(p) / p.w; };
    const int width = image.width, height = image.height;
    std::vector<char> covered(std::size_t(width * height), 0);
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i) {
            const double x = (i + 0.5) / width * 2 - 1, y = 1 - (j + 0.5) / height * 2;
            const glm::dvec3 a = dehomogenize(ndcFromObserverClip * glm::dvec4(x, y, 1, 1));
            const glm::dvec3 b = dehomogenize(ndcFromObserverClip * glm::dvec4(x, y, -1, 1));
            const glm::dvec3 aWorld = dehomogenize(worldFromNdc * glm::dvec4(a, 1));
            const glm::dvec3 d = dehomogenize(worldFromNdc * glm::dvec4(b, 1)) - aWorld;
            // |aWorld + t d|² = 1: both roots, each checked where it lands in NDC.
            const double qa = glm::dot(d, d), qb = 2 * glm::dot(aWorld, d), qc = glm::dot(aWorld, aWorld) - 1;
            const double disc = qb * qb - 4 * qa * qc;
            if (disc < 0) continue;
            for (double t : {(-qb - std::sqrt(disc)) / (2 * qa), (-qb + std::sqrt(disc)) / (2 * qa)}) {
                const glm::dvec4 cameraClip = cameraClipFromWorld * glm::dvec4(aWorld + t * d, 1);
                if (!(cameraClip.w > 0)) continue;
                const glm::dvec3 ndc = glm::dvec3(cameraClip) / cameraClip.w;
                const bool inZ = clip == NdcClip::XyOnly || std::abs(ndc.z) <= 1;
                if (std::abs(ndc.x) <= 1 && std::abs(ndc.y) <= 1 && inZ &&
                    (observerClipFromNdc * glm::dvec4(ndc, 1)).w > 0)
                    covered[std::size_t(j * width + i)] = 1;
            }
        }
    auto at = [&](int i, int j) { return covered[std::size_t(j * width + i)] != 0; };
    std::size_t wrong = 0;
    inside = 0;
    for (int j = 2; j < height - 2; ++j)
        for (int i = 2; i < width - 2; ++i) {
            bool edge = false;
            for (int dj = -2; dj <= 2; ++dj)
                for (int di = -2; di <= 2; ++di) edge |= at(i + di, j + dj) != at(i, j);
            if (edge || inLabel(labels, i, j)) continue; // a label's box may hide the sphere
            const std::size_t k = (std::size_t(j) * std::size_t(width) + std::size_t(i)) * 4;
            const double r = image.rgba[k] / 255.0, g = image.rgba[k + 1] / 255.0,
                         b = image.rgba[k + 2] / 255.0;
            const bool red = r > 0.5 && r > g + 0.4 && r > b + 0.4; // the sphere, under a face or not
            const bool line = g > 0.5;                              // a grey cube edge or a label's text
            inside += at(i, j);
            if (!line && red != at(i, j)) ++wrong;
        }
    return wrong;
}

// The NDC view of one flat red unit sphere at the origin, seen from the default eye (0, 0, 4): it spans
// distances 3 to 5, inside near 2.2 and far 6.
Scene flatRedSphereNdcScene() {
    Scene scene;
    scene.width = scene.height = 200;
    scene.projection = {ProjectionType::Perspective, 40, -1.4, 1.4, -1.4, 1.4, 2.2, 6};
    scene.view.kind = ViewKind::Ndc;
    scene.view.observer = {40, 20, 1};
    scene.objects[0].subdivisions = 7;
    // Flat red: every sphere pixel is told apart from the cube's grey lines and translucent faces.
    scene.objects[0].material = {{0.9, 0, 0}, {0, 0, 0}, {0, 0, 0}, 1};
    Light ambient;
    ambient.type = LightType::Ambient;
    ambient.ambient = {1, 1, 1};
    ambient.diffuse = ambient.specular = glm::dvec3(0);
    scene.lights = {ambient};
    return scene;
}

// The NDC view: the sphere drawn after M_proj·M_cam and the divide covers what the exact sphere covers
// there, under perspective (the egg) and orthographic projection.
TEST(NdcView, TheSpheresSilhouetteIsItsAnalyticImageUnderTheProjection) {
    SHADELAB_REQUIRE_GL(renderer);
    Scene scene = flatRedSphereNdcScene();
    for (ProjectionType type : {ProjectionType::Perspective, ProjectionType::Orthographic}) {
        SCOPED_TRACE(std::string(toString(type)));
        scene.projection.type = type;
        const Image image = renderer->render(scene);
        std::size_t inside = 0;
        const std::size_t wrong = ndcMismatches(image, scene, inside);
        EXPECT_GT(inside, 2000u) << "the analytic sphere covers a good part of the picture";
        EXPECT_EQ(wrong, 0u) << "pixels where the drawn sphere and its analytic image disagree";
        if (wrong) writePng(image, "ndc_view_failed.png"); // to look at
        // The comparison can fail: under a near plane at 1.6 the sphere is another egg.
        Scene otherNear = scene;
        otherNear.projection.near = 1.6;
        EXPECT_GT(ndcMismatches(image, otherNear, inside), 100u);
    }
}

// The NDC view clips in z as the clipper does (DESIGN §2: near -> NDC z = +1, far -> -1): a sphere the near
// plane cuts shows no front cap beyond the cube's near face, one the far plane cuts no back beyond its far
// face; through the cut the observer sees the sphere's inside. Each cut is seen from the side of the face
// that cuts it, where a cap left standing out of the cube covers pixels the cut sphere does not (from the
// near side the far cap hides behind the sphere). The eye stands at 8, so that the sphere is small in NDC x
// and y; the labels' boxes (which would hide it from the red test) are left out of the comparison.
TEST(NdcView, ASphereTheNearOrFarPlaneCutsEndsAtTheCubesFace) {
    SHADELAB_REQUIRE_GL(renderer);
    struct Cut {
        const char* name;
        double near, far;  // distances from the eye: the sphere spans 7 to 9
        double azimuthDeg; // the observer's
    };
    for (const Cut& cut : {Cut{"near plane at 7.5 cuts the front cap", 7.5, 10, 40},
                           Cut{"far plane at 8.4 cuts the back", 6, 8.4, 110}})
        for (ProjectionType type : {ProjectionType::Perspective, ProjectionType::Orthographic}) {
            SCOPED_TRACE(std::string(cut.name) + ", " + std::string(toString(type)));
            Scene scene = flatRedSphereNdcScene();
            scene.eye = {0, 0, 8};
            // Orthographic: a window of ±2.4 makes the sphere about as large in NDC x and y (±0.42) as
            // perspective's 40 degrees do.
            scene.projection = {type, 40, -2.4, 2.4, -2.4, 2.4, cut.near, cut.far};
            scene.view.observer = {cut.azimuthDeg, 20, 1};
            const Image image = renderer->render(scene);
            const std::vector<gl::ViewFigures::LabelBox> labels = renderer->viewFigures().labels;
            std::size_t inside = 0;
            const std::size_t wrong = ndcMismatches(image, scene, inside, NdcClip::Cube, labels);
            EXPECT_GT(inside, 1000u) << "the analytic cut sphere covers a good part of the picture";
            EXPECT_EQ(wrong, 0u) << "pixels where the drawn sphere and its analytic cut image disagree";
            if (wrong) writePng(image, "ndc_view_cut_failed.png"); // to look at
            // The cut shows: the same sphere left whole in z would cover other pixels of this picture.
            EXPECT_GT(ndcMismatches(image, scene, inside, NdcClip::XyOnly, labels), 100u);
        }
}

} // namespace
} // namespace shadelab::test
