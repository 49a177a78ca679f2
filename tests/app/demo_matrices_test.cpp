// The lecture's matrices as the panel, the page and render --print-matrices show them
// (src/app/demo/matrices_text.h): M_cam and M_proj as DESIGN §2 writes them, the normal matrix (the
// inverse transpose, or M itself when chosen), entries in columns of one width, float noise shown as the
// whole number.
#include "app/demo/matrices_text.h"

#include <cctype>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "demo_test_support.h"
#include "shadelab/scene/camera.h"
#include "shadelab/scene/scene.h"

namespace shadelab::app {
namespace {

using namespace demo_test;

// Reads the rows "[ a b c d ]" after the line that starts with `heading`.
std::vector<std::vector<double>> matrixAfter(const std::string& text, const std::string& heading, int rows) {
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line) && line.rfind(heading, 0) != 0) {
    }
    std::vector<std::vector<double>> out;
    while (int(out.size()) < rows && std::getline(in, line)) {
        const std::size_t open = line.find('[');
        if (open == std::string::npos || std::isalpha(static_cast<unsigned char>(line[open + 1])))
            continue; // a note under the heading: "[l,r] = ..."
        std::istringstream numbers(line.substr(line.find('[') + 1));
        std::vector<double> row;
        for (double x; numbers >> x;) row.push_back(x);
        out.push_back(row);
    }
    return out;
}

void expectMatrix(const std::vector<std::vector<double>>& shown, const glm::dmat4& expected,
                  const std::string& name) {
    ASSERT_EQ(shown.size(), 4u) << name;
    for (int r = 0; r < 4; ++r) {
        ASSERT_EQ(shown[std::size_t(r)].size(), 4u) << name << " row " << r;
        for (int c = 0; c < 4; ++c)
            EXPECT_NEAR(shown[std::size_t(r)][std::size_t(c)], expected[c][r], 5e-5)
                << name << " [" << r << "][" << c << "]";
    }
}

TEST(MatricesText, ShowsMCamAndTheWebGlMatrixAsTheLectureWritesThem) {
    Scene scene;
    scene.eye = {1, 2, 3};
    scene.target = {0, 0.5, 0};
    scene.width = 400;
    scene.height = 200;
    const std::string text = cameraMatricesText(scene);
    // M_cam is glm::lookAt (DESIGN §2); the projection is DESIGN §2's matrix written out with n = -near,
    // f = -far and the window of fovy and the aspect.
    expectMatrix(matrixAfter(text, "M_cam", 4), glm::lookAt(scene.eye, scene.target, scene.up), "M_cam");
    const double n = -0.5, f = -20, t = 0.5 * std::tan(20 * kDeg), r = 2 * t;
    glm::dmat4 webGl(0.0);
    webGl[0][0] = -2 * n / (2 * r);
    webGl[1][1] = -2 * n / (2 * t);
    webGl[2][2] = -(n + f) / (n - f);
    webGl[3][2] = 2 * f * n / (n - f);
    webGl[2][3] = -1;
    expectMatrix(matrixAfter(text, "M_proj", 4), webGl, "M_proj");
    EXPECT_NE(text.find("w = -z > 0"), std::string::npos) << text;
    scene.perspectiveMatrix = PerspectiveMatrix::Unnegated;
    const std::string unnegated = cameraMatricesText(scene);
    expectMatrix(matrixAfter(unnegated, "M_proj", 4), -webGl, "unnegated M_proj");
    EXPECT_NE(unnegated.find("w = z < 0"), std::string::npos) << unnegated;
}

TEST(MatricesText, TheNormalMatrixIsTheInverseTransposeOrMItself) {
    Scene scene;
    scene.objects[0].scale = {2, 1, 1};
    scene.objects[0].center = {0.5, 0, 0};
    const auto normal = [&] { return matrixAfter(objectMatricesText(scene, 0), "normal matrix", 3); };
    // The camera looks down -z from +z: M_cam's upper 3x3 is the identity, so the normal matrix of
    // scale(2, 1, 1) is diag(1/2, 1, 1), and M itself is diag(2, 1, 1).
    ASSERT_EQ(normal().size(), 3u);
    EXPECT_NEAR(normal()[0][0], 0.5, 1e-9);
    EXPECT_NEAR(normal()[1][1], 1, 1e-9);
    EXPECT_NE(objectMatricesText(scene, 0).find("((M_cam M)^-1)^T"), std::string::npos);
    scene.normalMatrix = NormalMatrixRule::Model;
    EXPECT_NEAR(normal()[0][0], 2, 1e-9);
    EXPECT_NE(objectMatricesText(scene, 0).find("wrong on purpose"), std::string::npos);
    const auto model = matrixAfter(objectMatricesText(scene, 0), "M (object 1", 4);
    ASSERT_EQ(model.size(), 4u);
    EXPECT_EQ(model[0], (std::vector<double>{2, 0, 0, 0.5}));
}

// Every matrix and vector row of `text`: "[", then entries of kEntryDigits + 1 characters, then " ]".
std::vector<std::string> matrixRows(const std::string& text) {
    std::vector<std::string> rows;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        const std::size_t open = line.find('[');
        if (open != std::string::npos && line.ends_with(" ]") && !std::isalpha(line[open + 1]))
            rows.push_back(line.substr(open + 1, line.size() - open - 3));
    }
    return rows;
}

// True when some entry of the scene's M_cam is float noise around a whole number (not one exactly).
bool mCamHasNoise(const Scene& scene) {
    const glm::dmat4 m = sceneView(scene).viewFromWorld;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (m[c][r] != std::round(m[c][r]) && std::abs(m[c][r] - std::round(m[c][r])) <= 1e-12)
                return true;
    return false;
}

// The panel, the page and render --print-matrices share this text. Entries stand in columns of one width
// with a space before each, up to 1e29 and negative; float noise around a whole number shows as
// that number, and 0 never as -0.
TEST(MatricesText, EntriesStandInFixedWidthColumnsWithASpaceBetween) {
    Scene far;
    far.eye = {1e29, 0, -1e29}; // M_cam's -w.e is -1.41e+29, beside 0.7071
    far.projection = {ProjectionType::Frustum, 40, -1e20, 1e20, -1e20, 1e20, 1e29, 1e30};
    Scene noisy;
    noisy.eye = {-3, 0, 1}; // an entry of M_cam is -1.11e-16
    noisy.target = {0, 0.5, 0};
    ASSERT_TRUE(mCamHasNoise(noisy)) << "this scene no longer shows float noise: choose another eye";
    for (const Scene& scene : {far, noisy}) {
        const std::string text = cameraMatricesText(scene) + objectMatricesText(scene, 0);
        const std::vector<std::string> rows = matrixRows(text);
        ASSERT_EQ(rows.size(), 4u + 4 + 4 + 4 + 3) << text; // e u v w, M_cam, M_proj, M, normal matrix
        for (const std::string& row : rows) {
            ASSERT_EQ(row.size() % (kEntryDigits + 1), 0u) << "columns of one width:\n" << text;
            for (std::size_t at = 0; at < row.size(); at += kEntryDigits + 1) {
                const std::string entry = row.substr(at, kEntryDigits + 1);
                EXPECT_EQ(entry[0], ' ') << "an entry touches the one before it: [" << row << "]\n" << text;
                std::istringstream in(entry);
                std::string token, rest;
                in >> token >> rest;
                EXPECT_TRUE(rest.empty()) << "one number per column: [" << row << "]";
                EXPECT_NE(token, "-0") << row;
                EXPECT_EQ(token.find("e-1"), std::string::npos) << "float noise shown as a number: " << row;
            }
        }
    }
    EXPECT_NE(cameraMatricesText(far).find("-1.41e+29"), std::string::npos);
}

TEST(MatricesText, FloatNoiseShowsAsTheWholeNumberAndZeroHasNoSign) {
    auto shown = [](double x) {
        std::istringstream in(matrixEntry(x));
        std::string token;
        in >> token;
        return token;
    };
    EXPECT_EQ(shown(-1.11e-16), "0");
    EXPECT_EQ(shown(-0.0), "0");
    EXPECT_EQ(shown(1 - 2e-16), "1");
    EXPECT_EQ(shown(-1 - 1e-13), "-1");
    EXPECT_EQ(shown(0.70710678), "0.7071");
    EXPECT_EQ(shown(-0.1919), "-0.1919");
    EXPECT_EQ(shown(-1e-11), "-1.00e-11") << "beyond 1e-12 of a whole number the value shows";
    EXPECT_EQ(shown(-1e300), "-1.0e+300");
    EXPECT_EQ(shown(-999.99996), "-1.00e+03") << "rounding to 4 decimals would take 10 characters";
    for (double x : {-1e300, -1.11e-16, -999.99996, 1e-300, -0.1919, 12345.678, 4.9e-324})
        EXPECT_EQ(matrixEntry(x).size(), kEntryDigits + 1) << x;
}

} // namespace
} // namespace shadelab::app
