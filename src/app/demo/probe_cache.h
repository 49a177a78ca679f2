// The probe (docs/students.md "The probe"): the surface point a click pinned, and its report for the drawn
// scene, kept until the drawn scene or the point changes. A level-10 mesh takes ~0.1 s to build and search,
// and a frame asks for the probe several times (its vectors, the panel's table, the title), so it is a cache
// keyed by the drawn scene's version (DemoState::drawnVersion) rather than recomputed or compared whole.
#pragma once

#include <cstdint>
#include <optional>

#include "shadelab/exact/probe.h"
#include "shadelab/geometry/sphere.h"
#include "shadelab/scene/scene.h"

namespace shadelab::app {

class ProbeCache {
public:
    void pin(const ProbePoint& point) { point_ = point; }
    void clear() { point_.reset(); }
    const std::optional<ProbePoint>& point() const { return point_; }

    // The report for the pinned point in `drawn`, whose version is `drawnVersion`: computed again only when
    // the version or the point changed; nullopt without a point or for a point on an object `drawn` lacks.
    const std::optional<ProbeReport>& report(const Scene& drawn, std::uint64_t drawnVersion);

private:
    std::optional<ProbePoint> point_;
    std::optional<ProbeReport> report_;
    std::optional<std::uint64_t> reportVersion_; // the drawn scene report_ was computed for
    // The mesh the last report searched: kept across versions, since an orbit or a colour changes no mesh.
    std::optional<SphereMesh> mesh_;
    VertexNormals meshNormals_ = VertexNormals::Averaged;
};

} // namespace shadelab::app
