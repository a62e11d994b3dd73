#include "rt/accel/make_accelerator.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "rt/accel/brute_force.h"
#include "rt/accel/bvh/bvh.h"
#include "rt/accel/octree/octree.h"
#include "rt/accel/octree_depth_for.h"
#include "rt/accel/seads/seads.h"
#if RT_WITH_EMBREE
#include "rt/accel/embree/embree_accelerator.h"
#endif
#include "rt/core/error.h"

namespace rt {

namespace {

constexpr std::array<std::pair<AccelKind, std::string_view>, 5> kNames{{
    {AccelKind::BruteForce, "brute"},
    {AccelKind::Octree, "octree"},
    {AccelKind::Seads, "seads"},
    {AccelKind::Bvh, "bvh"},
    {AccelKind::Embree, "embree"},
}};

}  // namespace

int suggested_seads_resolution(std::size_t polygons) {
    const double side = 0.7 * std::cbrt(static_cast<double>(polygons));
    return static_cast<int>(std::clamp(std::lround(side), 4L, 322L));
}

int suggested_octree_depth(std::size_t polygons) {
    const double count = static_cast<double>(std::max<std::size_t>(polygons, 1));
    return static_cast<int>(std::clamp(std::lround((std::log2(count) - 6.0) / 2.0), 1L, 20L));
}

std::string_view accel_kind_name(AccelKind kind) {
    for (const auto& [k, name] : kNames) {
        if (k == kind) {
            return name;
        }
    }
    return "?";
}

std::optional<AccelKind> accel_kind_from_name(std::string_view name) {
    for (const auto& [k, n] : kNames) {
        if (n == name) {
            return k;
        }
    }
    return std::nullopt;
}

AccelSettings method_for_scene(const Scene& scene, AccelSettings settings) {
    const SceneHeader& h = scene.header;
    const std::size_t polygons = scene.polygons.size();
    if (!settings.kind) {
        settings.kind = h.sptncde == 0   ? AccelKind::BruteForce
                        : h.sptncde == 1 ? AccelKind::Octree
                                         : AccelKind::Seads;
    }
    // A method the header does not name gets the voxel size measured best for the scene's size.
    // The suggested depth is measured on the scene (a few milliseconds on a big one), so only an
    // octree gets it.
    if (!settings.octree.depth && (h.sptncde == 1 || *settings.kind == AccelKind::Octree)) {
        settings.octree.depth = h.sptncde == 1 ? h.octr : octree_depth_for(scene);
    }
    if (!settings.seads_resolution) {
        settings.seads_resolution =
            h.sptncde > 1 ? h.sptncde : suggested_seads_resolution(polygons);
    }
    return settings;
}

std::unique_ptr<Accelerator> make_accelerator(const Scene& scene, const AccelSettings& asked) {
    const AccelSettings settings = method_for_scene(scene, asked);
    switch (*settings.kind) {
        case AccelKind::BruteForce:
            return make_brute_force(scene);
        case AccelKind::Octree:
            return make_octree(scene, settings);
        case AccelKind::Seads:
            return make_seads(scene, settings);
        case AccelKind::Bvh:
            return make_bvh(scene, BvhSettings{settings.build_threads});
        case AccelKind::Embree:
            break;
    }
#if RT_WITH_EMBREE
    return make_embree_accelerator(scene, settings.build_threads);
#else
    throw NotImplementedError(
        "the embree intersection method needs Embree 3, which this build of rt lacks");
#endif
}

}  // namespace rt
