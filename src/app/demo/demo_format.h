// Private to src/app/demo/: the number format that the state's messages (demo_state.cpp) and the probe
// table (demo_text.cpp) share.
#pragma once

#include <string>

#include <glm/vec3.hpp>

namespace shadelab::app {

// "(0.12, -3.40, 5.00)"
std::string formatVector(const glm::dvec3& v);

} // namespace shadelab::app
