#include "rt/app/accel_stack_settings.h"

#include "rt/accel/make_accelerator.h"
#include "rt/core/error.h"
#include "rt/core/text.h"

namespace rt {

AccelSettings accel_settings(const Scene& scene, const Options& o) {
    const SceneHeader& h = scene.header;
    AccelSettings a;
    a.kind = h.sptncde == 0   ? AccelKind::BruteForce
             : h.sptncde == 1 ? AccelKind::Octree
                              : AccelKind::Seads;
    // A method the header does not name gets the voxel size measured best for the scene's size.
    a.octree_depth = h.sptncde == 1 ? h.octr : suggested_octree_depth(scene.polygons.size());
    a.seads_resolution =
        h.sptncde > 1 ? h.sptncde : suggested_seads_resolution(scene.polygons.size());
    if (o.accel) {
        const std::optional<AccelKind> kind = accel_kind_from_name(*o.accel);
        if (!kind) {
            throw UsageError("--accel: expected brute, octree, seads, bvh or embree, found " +
                             quote_token(*o.accel));
        }
        a.kind = *kind;
    }
    if (o.octree_depth) {
        a.octree_depth = *o.octree_depth;
    }
    a.octlist_power = o.octlist_power;
    a.seed_size_power = o.seed_size_power;
    a.new_fillplane = o.new_fillplane;
    a.accept_near_hits = o.accept_near_hits;
    a.no_fudge = o.no_fudge;
    a.terminate_after_voxels = o.terminate_after_voxels;
    return a;
}

AcceleratorStackSettings accelerator_stack_settings(const Scene& scene, const Options& o,
                                                    const RunConsole& console) {
    AcceleratorStackSettings s;
    s.method = accel_settings(scene, o);
    s.exit_culling = !o.disable_exit_culling;
    s.check_exit_culling = o.debug_exit_culling;
    s.zbuffer_first_hits = o.zbuffer_first_hits;
    s.strike_check = o.debug_strike;
    s.strike_print = o.debug_strike_print;
    s.strike_voxels = o.debug_strike_oct;
    s.log_intersections = o.debug_intersections;
    s.trace_fill = o.debug_fillplane;
    if (o.debug_octree_output) {
        s.octree_listing = "octree.lst";
    }
    s.note = console.note;
    s.warning = console.warning;
    s.trace = console.trace;
    return s;
}

}  // namespace rt
