// What a level of the sphere costs, and the one check of a level (sphere.h): the memory a build and its
// GPU-ready arrays take, named in the message that refuses a level too high.
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "shadelab/errors.h"
#include "shadelab/geometry/mesh_layout.h"
#include "shadelab/geometry/sphere.h"

namespace shadelab {
namespace {

// Bytes for a level, in double so that absurd levels (asked for by mistake) do not wrap around.
double memoryBytes(int level) {
    level = std::min(level, 1000); // 2·level must not overflow int; 4^1000 is inf in double, which is fine
    const double f = std::ldexp(4.0, 2 * level), v = std::ldexp(2.0, 2 * level) + 2;
    // The mesh (positions and vertex normals; triangles and face normals), and the builder's second
    // triangle array (the levels alternate between the two).
    const double cpu = v * 2 * sizeof(glm::dvec3) + f * (2 * sizeof(glm::uvec3) + sizeof(glm::dvec3));
    // The last split's edge table (sphere.cpp): three edge numbers per parent (F/4 of them) and, per edge
    // of the parents' level (3F/8), the end point its first half starts from and its midpoint.
    const double edgeTable = (f / 4) * sizeof(glm::uvec3) + (3 * f / 8) * 2 * sizeof(std::uint32_t);
    const double gpuReady =
        std::max(meshBytes(level, MeshLayout::Smooth), meshBytes(level, MeshLayout::Flat));
    return cpu + edgeTable + gpuReady;
}

std::string humanBytes(double bytes) {
    static constexpr const char* kUnits[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB", "ZiB", "YiB"};
    int unit = 0;
    while (bytes >= 1024 && unit < 8) {
        bytes /= 1024;
        ++unit;
    }
    std::ostringstream out;
    out << std::fixed;
    out.precision(1);
    out << bytes << " " << kUnits[unit];
    return out.str();
}

} // namespace

std::size_t sphereMemoryBytes(int level) {
    const double bytes = memoryBytes(level);
    return bytes < double(std::numeric_limits<std::size_t>::max()) ? std::size_t(bytes)
                                                                   : std::numeric_limits<std::size_t>::max();
}

void checkSubdivisionLevel(int level, std::string_view field) {
    if (level < 0) {
        throw InputError(std::string(field) + ": must be between 0 and " + std::to_string(kMaxSubdivisions) +
                         ", got " + std::to_string(level));
    }
    if (level > kMaxSubdivisions) {
        const std::string triangles =
            level <= 30 ? " (" + std::to_string(sphereTriangleCount(level)) + " triangles)" : "";
        // Beyond about level 40 the figure leaves every unit (and double, past level 500): give its power of
        // two, from the per-triangle cost at a level where it is exact.
        const std::string need =
            level <= 40
                ? humanBytes(memoryBytes(level))
                : "2^" + std::to_string(long(std::floor(2.0 * level + std::log2(memoryBytes(20)) - 40))) +
                      " bytes";
        throw InputError(std::string(field) + ": level " + std::to_string(level) + " would need about " +
                         need + triangles + "; the maximum supported level is " +
                         std::to_string(kMaxSubdivisions) + " (" + humanBytes(memoryBytes(kMaxSubdivisions)) +
                         ")");
    }
}

// Out of memory in the middle of a build: what it needed and the ways out.
[[noreturn]] void detail::failSphereBuild(int level) {
    throw RuntimeError("out of memory building the level-" + std::to_string(level) + " sphere (" +
                       std::to_string(sphereTriangleCount(level)) + " triangles), which needs about " +
                       humanBytes(memoryBytes(level)) +
                       "; free memory or raise the limit (ulimit -v), or use a lower --subdivisions");
}

} // namespace shadelab
