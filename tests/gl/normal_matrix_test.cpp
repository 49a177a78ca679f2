// The scene's "normal_matrix" (DESIGN §2): normals transformed by (M⁻¹)ᵀ, the default, or by M itself, the
// lecture's wrong picture drawn on purpose. The wrong picture is held to the exact reference evaluated with
// the same wrong rule, within the bars of the right one; on a uniformly scaled sphere both rules agree.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "app/report/report.h"
#include "gl/gl_test_support.h"
#include "shadelab/gl/view_figures.h"

namespace shadelab::test {
namespace {

// A strongly non-uniform ellipsoid lit from the side: where M stretches x by 4 against y, normals by M tilt
// towards x and the lit side's shading visibly moves.
Scene stretchedEllipsoid(NormalMatrixRule rule) {
    SceneObject o;
    o.scale = {1.6, 0.4, 0.8};
    o.subdivisions = 8;
    Scene scene = litSphereScene(256, LightType::Point);
    scene.objects = {o};
    scene.normalMatrix = rule;
    return scene;
}

Scene withModel(Scene scene, LightingModel model, ShadingMode mode) {
    scene.lighting = model;
    scene.shading = mode;
    return scene;
}

// Phong at level 8 and exact shading, both lighting models, against the ray-cast reference with normals by
// M: the bars of the right rule (analytic_test.cpp and exact_test.cpp). The two references also differ (by
// more than 10/255 on a part of the ellipsoid), so a renderer that ignored the rule would fail here.
TEST(NormalMatrix, NormalsByModelMatchTheReferenceWithTheSameRule) {
    SHADELAB_REQUIRE_GL(renderer);
    for (LightingModel model : kLightingModels) {
        const Scene wrong = withModel(stretchedEllipsoid(NormalMatrixRule::Model), model, ShadingMode::Phong);
        const ReferenceImage expected = renderReference(wrong);
        const ReferenceImage right = renderReference(
            withModel(stretchedEllipsoid(NormalMatrixRule::InverseTranspose), model, ShadingMode::Phong));
        std::size_t moved = 0, covered = 0;
        for (std::size_t i = 0; i < expected.objectId.size(); ++i) {
            if (expected.objectId[i] < 0) continue;
            ++covered;
            for (int c = 0; c < 3; ++c)
                if (std::abs(expected.color.rgba[4 * i + c] - right.color.rgba[4 * i + c]) > 10.0f / 255) {
                    ++moved;
                    break;
                }
        }
        SCOPED_TRACE(std::string(toString(model)));
        ASSERT_GT(covered, 5000u);
        EXPECT_GT(moved, covered / 20) << "the wrong rule's reference barely differs from the right one's";

        const InteriorError phong = interiorError(renderer->renderFloat(wrong), expected);
        std::printf("normals by M, %s, phong level 8: interior mean %.3f/255, max %.3f/255 over %zu pixels; "
                    "%zu of %zu pixels moved by > 10/255 from (M^-1)^T's\n",
                    toString(model).data(), phong.mean, phong.max, phong.pixels, moved, covered);
        ASSERT_GT(phong.pixels, 1000u);
        EXPECT_LT(phong.mean, 0.5) << "mean interior error in 1/255 units";
        EXPECT_LE(phong.max, 4.0) << "max interior error in 1/255 units";

        const Scene exact = withModel(wrong, model, ShadingMode::Exact);
        const InteriorError e = interiorError(renderer->renderFloat(exact), renderReference(exact));
        std::printf("normals by M, %s, exact: interior mean %.3f/255, max %.3f/255\n", toString(model).data(),
                    e.mean, e.max);
        EXPECT_LE(e.mean, 0.05);
        EXPECT_LE(e.max, 2.0);
    }
}

// The error view's exact is the truth, normals by (M⁻¹)ᵀ: with normals by M it shows what the wrong matrix
// costs (its figures are report's measure against withTrueNormals' reference), where with the right one it
// shows only the mesh's error.
TEST(NormalMatrix, TheErrorViewShowsWhatTheWrongMatrixCosts) {
    SHADELAB_REQUIRE_GL(renderer);
    double mean[2] = {0, 0};
    for (const NormalMatrixRule rule : kNormalMatrixRules) {
        Scene scene = stretchedEllipsoid(rule);
        scene.objects[0].subdivisions = 6;
        const app::ReportError report =
            app::measureError(renderer->renderFloat(scene), renderReference(withTrueNormals(scene)));
        scene.view = parseView("error").view.value();
        renderer->render(scene);
        const gl::ViewFigures& f = renderer->viewFigures();
        std::printf("error view, normals by %s: mean %.3f/255, max %.3f/255; report %.3f/255, %.3f/255\n",
                    toString(rule).data(), f.interiorMean, f.interiorMax, report.interiorMean,
                    report.interiorMax);
        EXPECT_NEAR(f.interiorMean, report.interiorMean, 0.05) << toString(rule);
        EXPECT_NEAR(f.interiorMax, report.interiorMax, 0.05) << toString(rule);
        mean[std::size_t(rule)] = f.interiorMean;
    }
    EXPECT_LT(mean[0], 0.5) << "the mesh's own error, normals by (M^-1)^T";
    EXPECT_GT(mean[1], 10 * mean[0] + 2) << "normals by M cost nothing in the error view";
}

// Under a uniform scale M = s·R, and M and (M⁻¹)ᵀ = R/s give every normal the same direction: the two rules
// draw the same picture, in every shading mode (flat through the face normal attribute).
TEST(NormalMatrix, BothRulesAgreeOnAUniformlyScaledSphere) {
    SHADELAB_REQUIRE_GL(renderer);
    Scene scene = litSphereScene(128, LightType::Point);
    for (SceneObject& o : scene.objects) {
        o.scale = {0.7, 0.7, 0.7};
        o.subdivisions = 4;
    }
    for (ShadingMode mode : kAllShadingModes) {
        scene.shading = mode;
        scene.normalMatrix = NormalMatrixRule::InverseTranspose;
        const Image right = renderer->render(scene);
        scene.normalMatrix = NormalMatrixRule::Model;
        const Image byModel = renderer->render(scene);
        int worst = 0;
        std::size_t covered = 0;
        for (std::size_t i = 0; i < right.rgba.size(); ++i) {
            worst = std::max(worst, std::abs(int(right.rgba[i]) - int(byModel.rgba[i])));
            if (i % 4 == 3 && right.rgba[i] > 0) ++covered;
        }
        SCOPED_TRACE(std::string(toString(mode)));
        EXPECT_GT(covered, 2000u);
        EXPECT_LE(worst, 1) << "the rules disagree under a uniform scale";
    }
}

} // namespace
} // namespace shadelab::test
