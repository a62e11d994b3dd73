#include "rt/scene/scene.h"

namespace rt {

SourceLocation Scene::origin_of(std::uint32_t polygon) const {
    const SourceRef& ref = polygon_origin.at(polygon);
    return {source_files.at(ref.file), static_cast<int>(ref.line), 0};
}

Box3 Scene::bounds() const {
    if (positions.empty()) {
        return Box3::around(Vec3{});
    }
    Box3 box = Box3::around(positions.front());
    for (const Vec3& p : positions) {
        box.add(p);
    }
    return box;
}

}  // namespace rt
