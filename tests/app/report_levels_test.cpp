// The levels `shadelab report` measures a scene at (src/app/report/report.h reportLevels): the asked range
// within the levels of the scene's shapes (DESIGN §1: the sphere's 0..10, the teapot's 0..8, none for a
// model's own mesh), then "auto". The rows themselves are measured end to end by
// tests/cli/cli_models_test.cpp.
#include <vector>

#include <gtest/gtest.h>

#include "app/report/report.h"
#include "shadelab/geometry/sphere.h"
#include "shadelab/geometry/teapot.h"

namespace shadelab::app {
namespace {

Scene sceneOf(std::vector<Shape> shapes) {
    Scene scene;
    scene.objects.clear();
    for (Shape shape : shapes) {
        SceneObject object;
        object.shape = shape;
        if (shape == Shape::Mesh) object.mesh = "models/x.obj";
        scene.objects.push_back(object);
    }
    return scene;
}

ReportOptions levels(int lo, int hi, bool includeAuto) {
    ReportOptions options;
    options.minLevel = lo;
    options.maxLevel = hi;
    options.includeAuto = includeAuto;
    return options;
}

TEST(ReportLevels, ATeapotSceneStopsAtTheTeapotsFinestLevel) {
    const Scene teapot = sceneOf({Shape::Teapot});
    EXPECT_EQ(reportLevels(teapot, levels(0, kMaxSubdivisions, false)),
              (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 8}));
    EXPECT_EQ(reportLevels(teapot, levels(8, 10, true)), (std::vector<int>{8, kAutoSubdivisions}));
    EXPECT_EQ(reportLevels(teapot, levels(0, 8, true)).size(), std::size_t(kMaxTeapotLevel) + 2);
}

TEST(ReportLevels, ASphereBesideTheTeapotKeepsTheSpheresLevels) {
    EXPECT_EQ(reportLevels(sceneOf({Shape::Sphere}), levels(7, 10, false)), (std::vector<int>{7, 8, 9, 10}));
    EXPECT_EQ(reportLevels(sceneOf({Shape::Teapot, Shape::Sphere}), levels(7, 10, false)),
              (std::vector<int>{7, 8, 9, 10}));
}

TEST(ReportLevels, ModelsOnlyHaveTheirOwnMesh) {
    EXPECT_EQ(reportLevels(sceneOf({Shape::Mesh}), levels(0, 8, true)), std::vector<int>{0});
}

} // namespace
} // namespace shadelab::app
