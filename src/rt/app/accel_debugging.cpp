#include "rt/app/accel_debugging.h"

#include <string>

#include "rt/accel/debug/intersection_log.h"
#include "rt/accel/octree/octree.h"
#include "rt/accel/octree/octree_listing.h"
#include "rt/core/atomic_file.h"

namespace rt {

namespace {

void write_octree_file(const Accelerator& accel, const RunConsole& console) {
    const auto* octree = dynamic_cast<const Octree*>(&accel);
    if (octree == nullptr) {
        console.note("-doo: the intersection method is " + std::string(accel.name()) +
                     ", not an octree: no octree.lst written");
        return;
    }
    write_file_atomically("octree.lst",
                          [&](std::ostream& out) { write_octree_listing(octree->tree(), out); });
}

}  // namespace

DebuggedAccelerator add_accel_debugging(const Scene& scene, std::unique_ptr<Accelerator> accel,
                                        const Options& options, const RunConsole& console) {
    if (options.debug_octree_output) {
        write_octree_file(*accel, console);
    }
    DebuggedAccelerator out;
    // -dsp and -dso only make sense with the check, so they imply -ds.
    if (options.debug_strike || options.debug_strike_print || options.debug_strike_oct) {
        auto strike = std::make_unique<StrikeCheck>(
            scene, std::move(accel),
            StrikeOptions{options.debug_strike_print, options.debug_strike_oct},
            [trace = console.trace](const std::string& line) {
                if (trace) {
                    trace(line);
                }
            });
        out.strike = strike.get();
        accel = std::move(strike);
    }
    if (options.debug_intersections) {
        accel = std::make_unique<IntersectionLog>(std::move(accel),
                                                  [trace = console.trace](const std::string& line) {
                                                      if (trace) {
                                                          trace(line);
                                                      }
                                                  });
    }
    out.accel = std::move(accel);
    return out;
}

}  // namespace rt
