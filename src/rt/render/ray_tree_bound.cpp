#include "rt/render/ray_tree_bound.h"

#include <algorithm>
#include <vector>

#include "rt/shading/lights.h"

namespace rt {

namespace {

// The secondary rays one hit on a surface of attribute `a` sends (as RayTracer::secondary_rays
// does), with `lobe_rays` rays in each distributed lobe.
double branching(const Attribute& a, const ShadingSettings& settings, bool diffuse_rays,
                 bool distribute, double lobe_rays) {
    double rays = 0.0;
    if (settings.reflection && a.specular > 0.0) {
        rays += distribute && a.reflect_cone_degrees > 0.0 ? lobe_rays : 1.0;
    }
    if (a.transmission > 0.0) {
        const Rgb& n = a.refraction_index;
        const double channels = n.r != n.g || n.g != n.b ? 3.0 : 1.0;  // -R splits the colours
        rays += channels * (distribute && a.refract_cone_degrees > 0.0 ? lobe_rays : 1.0);
    }
    if (diffuse_rays && a.diffuse > 0.0) {
        rays += distribute ? lobe_rays : 1.0;
    }
    return rays;
}

}  // namespace

RayTreeBound ray_tree_bound(const Scene& scene, const ShadingSettings& settings) {
    const bool diffuse_rays = !settings.shadow_feelers || scene.header.lghtick == 0;
    double feelers_per_hit = 0.0;
    if (!diffuse_rays) {
        const std::size_t lights = collect_point_lights(scene, scene.header.lghtick).size();
        feelers_per_hit = static_cast<double>(lights) *
                          (settings.fuzzy.enabled() ? std::max(1, settings.fuzzy.count) : 1);
    }
    std::vector<char> used(scene.attributes.size(), 0);
    for (const Polygon& p : scene.polygons) {
        used[p.attribute] = 1;
    }
    const double lobe_rays = static_cast<double>(scene.view.sample_resolution_x) *
                             static_cast<double>(scene.view.sample_resolution_y);
    RayTreeBound bound;
    double rays_at_depth = 1.0;  // the eye ray
    double total = 0.0;
    for (int depth = 1; depth <= scene.header.maxdepth; ++depth) {
        total += rays_at_depth * (1.0 + feelers_per_hit);
        if (depth == scene.header.maxdepth) {
            break;
        }
        const bool distribute = settings.sampling.distribute && depth <= scene.header.maxdist;
        double widest = 0.0;
        for (std::size_t i = 0; i < used.size(); ++i) {
            if (used[i] != 0) {
                widest = std::max(widest, branching(scene.attributes[i], settings, diffuse_rays,
                                                    distribute, lobe_rays));
            }
        }
        if (depth == 1) {
            bound.widest_branching = widest;
        }
        rays_at_depth *= widest;
        if (rays_at_depth == 0.0) {
            break;
        }
    }
    bound.rays_per_sample = total;
    return bound;
}

}  // namespace rt
