// What the scene file's tests share (tests/scene/scene_parse_test.cpp, scene_check_test.cpp,
// scene_json_test.cpp): DESIGN §4's example, a check that a message holds every expected piece,
// field-by-field comparisons of scenes, and readable failures for vectors. Each test file's anonymous
// namespace says `using namespace scene_test;`.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "shadelab/scene/scene.h"

namespace glm {
// Readable failures for EXPECT_EQ on vectors (gtest finds PrintTo by argument-dependent lookup).
inline void PrintTo(const dvec3& v, std::ostream* os) {
    *os << "[" << v.x << ", " << v.y << ", " << v.z << "]";
}
} // namespace glm

namespace shadelab::scene_test {

// The example of DESIGN §4, verbatim: it must describe exactly the defaults.
inline constexpr const char* kDesignExample = R"({
  "image":      { "width": 512, "height": 512, "background": [0, 0, 0] },
  "camera":     { "eye": [0, 0, 4], "target": [0, 0, 0], "up": [0, 1, 0] },
  "projection": { "type": "perspective", "fovy_deg": 40, "near": 0.5, "far": 20 },
  "shading":    "phong",
  "lighting":   "blinn-phong",
  "objects": [
    { "center": [0, 0, 0], "radius": 1, "scale": [1, 1, 1], "subdivisions": 5,
      "material": { "ambient": [0.1, 0.1, 0.1], "diffuse": [0.7, 0.2, 0.2],
                    "specular": [1, 1, 1], "shininess": 32 } }
  ],
  "lights": [
    { "type": "point", "position": [3, 3, 5], "ambient": [0.1, 0.1, 0.1],
      "diffuse": [1, 1, 1], "specular": [1, 1, 1], "attenuation": [1, 0, 0] }
  ]
})";

inline ::testing::AssertionResult containsAll(const std::string& message,
                                              const std::vector<std::string>& parts) {
    for (const std::string& part : parts)
        if (message.find(part) == std::string::npos)
            return ::testing::AssertionFailure() << "message \"" << message << "\" lacks \"" << part << "\"";
    return ::testing::AssertionSuccess();
}

inline void expectSameLight(const Light& a, const Light& b) {
    EXPECT_EQ(a.type, b.type);
    EXPECT_EQ(a.ambient, b.ambient);
    EXPECT_EQ(a.diffuse, b.diffuse);
    EXPECT_EQ(a.specular, b.specular);
    EXPECT_EQ(a.position, b.position);
    EXPECT_EQ(a.direction, b.direction);
    EXPECT_EQ(a.cutoffDeg, b.cutoffDeg);
    EXPECT_EQ(a.exponent, b.exponent);
    EXPECT_EQ(a.attenuation, b.attenuation);
}

inline void expectSameObject(const SceneObject& a, const SceneObject& b) {
    EXPECT_EQ(a.center, b.center);
    EXPECT_EQ(a.radius, b.radius);
    EXPECT_EQ(a.scale, b.scale);
    EXPECT_EQ(a.subdivisions, b.subdivisions);
    EXPECT_EQ(a.material.ambient, b.material.ambient);
    EXPECT_EQ(a.material.diffuse, b.material.diffuse);
    EXPECT_EQ(a.material.specular, b.material.specular);
    EXPECT_EQ(a.material.shininess, b.material.shininess);
}

inline void expectSameScene(const Scene& a, const Scene& b) {
    EXPECT_EQ(a.width, b.width);
    EXPECT_EQ(a.height, b.height);
    EXPECT_EQ(a.background, b.background);
    EXPECT_EQ(a.eye, b.eye);
    EXPECT_EQ(a.target, b.target);
    EXPECT_EQ(a.up, b.up);
    EXPECT_EQ(a.projection.type, b.projection.type);
    EXPECT_EQ(a.projection.fovyDeg, b.projection.fovyDeg);
    EXPECT_EQ(a.projection.left, b.projection.left);
    EXPECT_EQ(a.projection.right, b.projection.right);
    EXPECT_EQ(a.projection.bottom, b.projection.bottom);
    EXPECT_EQ(a.projection.top, b.projection.top);
    EXPECT_EQ(a.projection.near, b.projection.near);
    EXPECT_EQ(a.projection.far, b.projection.far);
    EXPECT_EQ(a.shading, b.shading);
    EXPECT_EQ(a.lighting, b.lighting);
    EXPECT_EQ(a.term, b.term);
    EXPECT_EQ(a.toonBands, b.toonBands);
    EXPECT_EQ(a.tolerancePx, b.tolerancePx);
    EXPECT_EQ(a.depth, b.depth);
    EXPECT_EQ(a.vertexNormals, b.vertexNormals);
    EXPECT_EQ(a.normalMatrix, b.normalMatrix);
    EXPECT_EQ(a.perspectiveMatrix, b.perspectiveMatrix);
    ASSERT_EQ(a.objects.size(), b.objects.size());
    for (std::size_t i = 0; i < a.objects.size(); ++i) expectSameObject(a.objects[i], b.objects[i]);
    ASSERT_EQ(a.lights.size(), b.lights.size());
    for (std::size_t i = 0; i < a.lights.size(); ++i) expectSameLight(a.lights[i], b.lights[i]);
}

} // namespace shadelab::scene_test
