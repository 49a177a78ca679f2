#include "app/demo/probe_cache.h"

#include "shadelab/scene/auto_level.h"

namespace shadelab::app {

const std::optional<ProbeReport>& ProbeCache::report(const Scene& drawn, std::uint64_t drawnVersion) {
    if (!point_ || point_->object >= drawn.objects.size()) {
        report_.reset();
        reportVersion_.reset();
        return report_;
    }
    if (report_ && reportVersion_ == drawnVersion && report_->point == *point_) return report_;
    const int level = subdivisionLevel(drawn, drawn.objects[point_->object]);
    if (!mesh_ || mesh_->level != level || meshNormals_ != drawn.vertexNormals) {
        mesh_ = buildSphere(level, drawn.vertexNormals);
        meshNormals_ = drawn.vertexNormals;
    }
    report_ = probeSurface(drawn, *point_, *mesh_);
    reportVersion_ = drawnVersion;
    return report_;
}

} // namespace shadelab::app
