// What the sphere's overlay (overlay.cpp) and the other shapes' (mesh_overlay.cpp) draw their lines with.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "shadelab/diagram/overlay.h"

namespace shadelab::detail {

inline void segment(std::vector<LineVertex>& lines, const glm::dvec3& from, const glm::dvec3& to,
                    glm::vec3 color) {
    lines.push_back({glm::vec3(from), color});
    lines.push_back({glm::vec3(to), color});
}

// Where a normal line drawn from `from` ends, in object space: once the object's matrix M (its linear part
// `worldFromObject`) is applied, the line runs from M·from along `normalWorldFromObject`·n, the normal the
// shading uses, and is `worldLength` long. A line drawn in object space and then taken through M would turn
// along M·n whatever the rule, which is the shading's normal only under rotations and uniform scales.
struct NormalTips {
    glm::dmat3 objectFromWorld, normalWorldFromObject;
    double worldLength;
    glm::dvec3 operator()(const glm::dvec3& from, const glm::dvec3& normalObject) const {
        const glm::dvec3 normalWorld = glm::normalize(normalWorldFromObject * normalObject);
        return from + objectFromWorld * (worldLength * normalWorld);
    }
};

} // namespace shadelab::detail
