#include "gl/extreme_support.h"
#include "tolerances.h"

#include <algorithm>
#include <cstdio>

#include <gtest/gtest.h>

namespace shadelab::test {

void expectClean(const ImageF& image, const std::string& what) {
    const ValueScan scan = scanValues(image);
    EXPECT_EQ(scan.nonFinite, 0u) << what << ": non-finite values in the image";
    EXPECT_EQ(scan.outOfRange, 0u) << what << ": values outside [0, 1] in the image";
}

ImageF checkedRender(HeadlessRenderer& renderer, const Scene& scene, const std::string& what) {
    ImageF image = renderer.renderFloat(scene);
    EXPECT_EQ(image.width, scene.width) << what;
    EXPECT_EQ(image.height, scene.height) << what;
    expectClean(image, what);
    return image;
}

ReferenceImage checkedReference(const Scene& scene, const std::string& what) {
    ReferenceImage reference = renderReference(scene);
    expectClean(reference.color, what + " (reference)");
    return reference;
}

std::size_t coveredPixels(const ImageF& image) {
    std::size_t n = 0;
    for (std::size_t i = 3; i < image.rgba.size(); i += 4) n += image.rgba[i] > 0.5f;
    return n;
}

std::size_t coveredPixels(const ReferenceImage& reference) {
    return std::size_t(
        std::count_if(reference.objectId.begin(), reference.objectId.end(), [](int id) { return id >= 0; }));
}

void expectPhongLimits(const ImageF& image, const ReferenceImage& reference, const std::string& what,
                       std::size_t minPixels) {
    const InteriorError e = interiorError(image, reference);
    std::printf("  %s: interior mean %.3f/255, max %.3f/255 over %zu pixels\n", what.c_str(), e.mean, e.max,
                e.pixels);
    EXPECT_GE(e.pixels, minPixels) << what << ": the interior is nearly empty";
    EXPECT_LT(e.mean, 0.5) << what << ": mean interior error in 1/255 units";
    EXPECT_LE(e.max, 4.0) << what << ": max interior error in 1/255 units";
}

void expectSameImage(const ImageF& actual, const ImageF& expected, const std::string& what) {
    const Comparison c = compareImages(toImage8(actual), toImage8(expected), kRegressionTolerance);
    std::printf("  %s: %s\n", what.c_str(), c.summary().c_str());
    EXPECT_TRUE(c.passed) << what << ": " << c.summary();
}

Scene phongScene(int size, LightType light) {
    Scene scene = litSphereScene(size, light);
    scene.shading = ShadingMode::Phong;
    scene.objects[0].subdivisions = 8;
    return scene;
}

const char* normalsName(VertexNormals normals) {
    return normals == VertexNormals::Exact ? "exact-normals" : "averaged-normals";
}

} // namespace shadelab::test
