#include "rt/app/accelerator_stack.h"

#include "rt/accel/make_accelerator.h"
#include "rt/app/accel_debugging.h"
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

namespace {

// The header names only methods every build has (brute force, the octree, SEADS); a method this
// build lacks can only come from --accel, and is refused (NotImplementedError).
std::unique_ptr<Accelerator> build_accelerator(const Scene& scene, const Options& o,
                                               const RunConsole& console) {
    AccelSettings settings = accel_settings(scene, o);
    if (o.debug_fillplane) {
        settings.fill_trace = console.trace;
        if (!settings.new_fillplane || settings.kind != AccelKind::Octree) {
            console.note("-dof traces the -op octree fill only; nothing to trace here");
        }
    }
    return make_accelerator(scene, settings);
}

}  // namespace

AcceleratorStack::AcceleratorStack(const Scene& scene, const Options& options,
                                   const RunConsole& console) {
    // -doo, -ds, -dsp, -dso and -dl look at the method itself, inside exit culling.
    DebuggedAccelerator debugged =
        add_accel_debugging(scene, build_accelerator(scene, options, console), options, console);
    base_ = std::move(debugged.accel);
    strike_ = debugged.strike;
    if (!options.disable_exit_culling) {
        ExitCullingSettings culling;
        culling.check_culled = options.debug_exit_culling;
        auto wrapped = std::make_unique<ExitCulling>(scene, std::move(base_), culling);
        culling_ = wrapped.get();
        base_ = std::move(wrapped);
    }
    top_ = base_.get();
    if (options.zbuffer_first_hits) {
        zbuffer_ = make_zbuffer_first_hits(scene, scene.view.camera(), *base_);
        const ZBufferStatistics z = zbuffer_->statistics();
        if (!z.active) {
            console.warning("z-buffer off: " + z.inactive_reason +
                            "; eye rays use the intersection method");
        }
        top_ = zbuffer_.get();
    }
}

std::vector<std::string> AcceleratorStack::report_lines() const {
    std::vector<std::string> lines;
    if (culling_ != nullptr) {
        for (std::string& line : describe(culling_->statistics())) {
            lines.push_back(std::move(line));
        }
    }
    if (zbuffer_) {
        for (std::string& line : describe(zbuffer_->statistics())) {
            lines.push_back(std::move(line));
        }
    }
    return lines;
}

}  // namespace rt
