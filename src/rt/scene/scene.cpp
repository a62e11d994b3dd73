#include "rt/scene/scene.h"

namespace rt {

SourceLocation Scene::origin_of(std::uint32_t polygon) const {
    const SourceRef& ref = polygon_origin.at(polygon);
    return {source_files.at(ref.file), static_cast<int>(ref.line), 0};
}

void Scene::bounds(Vec3& lo, Vec3& hi) const {
    if (positions.empty()) {
        lo = hi = Vec3{};
        return;
    }
    lo = hi = positions.front();
    for (const Vec3& p : positions) {
        lo = min_components(lo, p);
        hi = max_components(hi, p);
    }
}

}  // namespace rt
