// -doi, "Debug octree interactively" (manual, Appendix: in the original it "doesn't work"): a
// session that walks the built octree, one command a line. Go down to a child by its octant, back
// up, list a node's box and its polygons, find the leaf holding a point, and follow a ray (or the
// eye ray through a pixel) leaf by leaf as the DDDA steps, with the hit it finds. The commands
// come from a stream, so a script can drive it; `help` lists them.
#pragma once

#include <istream>
#include <ostream>
#include <string>

#include "rt/accel/octree/octree.h"
#include "rt/scene/scene.h"

namespace rt {

struct OctreeSessionStreams {
    std::istream& commands;
    std::ostream& answers;
    /// Printed before each command is read ("octree> " when a person types them), or empty.
    std::string prompt;
};

/// Runs the session until `quit` or the end of the commands. A bad command gets one line saying
/// what is wrong and the session goes on. Returns how many commands failed.
int run_octree_session(const Scene& scene, const Octree& octree, OctreeSessionStreams streams);

}  // namespace rt
