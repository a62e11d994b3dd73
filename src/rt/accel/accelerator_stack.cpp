#include "rt/accel/accelerator_stack.h"

#include "rt/accel/debug/intersection_log.h"
#include "rt/accel/make_accelerator.h"
#include "rt/accel/octree/octree.h"
#include "rt/accel/octree/octree_listing.h"
#include "rt/core/atomic_file.h"

#include <fmt/format.h>

namespace rt {

namespace {

void send(const TextSink& sink, const std::string& line) {
    if (sink) {
        sink(line);
    }
}

// A sink that may be empty, as the layers want it: always callable.
TextSink callable(const TextSink& sink) {
    return [sink](const std::string& line) { send(sink, line); };
}

std::unique_ptr<Accelerator> build_method(const Scene& scene, const AcceleratorStackSettings& s,
                                          const AccelMessages& m) {
    AccelSettings method = method_for_scene(scene, s.method);
    if (s.trace_fill) {
        method.octree.fill_trace = m.trace;
        if (!method.octree.level_order || method.kind != AccelKind::Octree) {
            send(m.note, "-dof traces the -op octree fill only; nothing to trace here");
        }
    }
    return make_accelerator(scene, method);
}

void write_octree_listing_of(const Accelerator& accel, const std::filesystem::path& path,
                             const TextSink& note) {
    const auto* octree = dynamic_cast<const Octree*>(&accel);
    if (octree == nullptr) {
        send(note, "-doo: the intersection method is " + std::string(accel.name()) +
                       ", not an octree: no " + path.filename().string() + " written");
        return;
    }
    write_file_atomically(path,
                          [&](std::ostream& out) { write_octree_listing(octree->tree(), out); });
}

}  // namespace

std::string exit_culling_left_out(const Scene& scene, const AcceleratorStackSettings& s) {
    // The table's build takes about 0.2 us a polygon (0.19 s for a million triangles, 1.5 s for
    // ten million), and the only rays its cells cull are rays from the eye, each of which would
    // otherwise cost at most a walk that meets nothing, mostly far less: with more polygons than
    // such rays it cannot save what it costs. (The leaving table, which culls rays leaving a
    // polygon, is built for small scenes only.)
    const std::uint64_t polygons = scene.polygons.size();
    if (!s.exit_culling || s.check_exit_culling || s.most_eye_rays == 0 ||
        polygons <= s.most_eye_rays) {
        return {};
    }
    return fmt::format(
        "{} polygons, more than the {} rays from the eye it could cull; -de keeps it", polygons,
        s.most_eye_rays);
}

AcceleratorStack::AcceleratorStack(const Scene& scene, const AcceleratorStackSettings& s,
                                   const AccelMessages& m) {
    base_ = build_method(scene, s, m);
    if (s.octree_listing) {
        write_octree_listing_of(*base_, *s.octree_listing, m.note);
    }
    // The debugging layers look at the method itself, inside exit culling.
    if (s.strike_check || s.strike_print || s.strike_voxels) {
        auto strike = std::make_unique<StrikeCheck>(scene, std::move(base_),
                                                    StrikeOptions{s.strike_print, s.strike_voxels},
                                                    callable(m.trace));
        strike_ = strike.get();
        base_ = std::move(strike);
    }
    if (s.log_intersections) {
        base_ = std::make_unique<IntersectionLog>(std::move(base_), callable(m.trace));
    }
    culling_left_out_ = exit_culling_left_out(scene, s);
    if (s.exit_culling && culling_left_out_.empty()) {
        ExitCullingSettings culling;
        culling.check_culled = s.check_exit_culling;
        culling.build_threads = static_cast<int>(s.method.build_threads);
        // Near hits unverified (-on), no fudge (-of) and giving up after some voxels (-tv) make the
        // method answer otherwise than brute force on purpose, and -ds and -dl watch its answers:
        // then every ray exit culling does not cull goes to it.
        const bool method_as_asked = s.method.accept_near_hits || s.method.no_fudge ||
                                     s.method.terminate_after_voxels.has_value();
        const bool watched =
            s.strike_check || s.strike_print || s.strike_voxels || s.log_intersections;
        culling.answers = !method_as_asked && !watched;
        // The z-buffer above answers the eye rays first.
        culling.eye_items = !s.zbuffer_first_hits;
        auto wrapped = std::make_unique<ExitCulling>(scene, std::move(base_), culling);
        culling_ = wrapped.get();
        base_ = std::move(wrapped);
    }
    top_ = base_.get();
    if (s.zbuffer_first_hits) {
        zbuffer_ = make_zbuffer_first_hits(scene, scene.view.camera(), *base_);
        const ZBufferStatistics z = zbuffer_->statistics();
        if (!z.active) {
            send(m.warning,
                 "z-buffer off: " + z.inactive_reason + "; eye rays use the intersection method");
        }
        top_ = zbuffer_.get();
    }
}

std::vector<std::string> AcceleratorStack::report_lines() const {
    std::vector<std::string> lines;
    if (!culling_left_out_.empty()) {
        lines.push_back("exit culling: off (" + culling_left_out_ + ")");
    }
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
