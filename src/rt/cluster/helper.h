// A rank other than 0 in a cluster run: asks rank 0 for rows, renders them on its threads, and
// sends each finished row back; its last message says it is done or why it failed.
#pragma once

#include <string>

#include "rt/cluster/mpi_world.h"
#include "rt/render/renderer.h"

namespace rt::cluster {

class Helper {
public:
    /// identity: what this rank renders (scene and switches), for rank 0 to check.
    Helper(MpiWorld& world, std::string identity);

    /// Renders the rows rank 0 hands out until it has no more or says stop. Throws what the
    /// renderer throws, and ClusterError when this process gets a signal.
    void render(const Scene& scene, const Accelerator& accel, const RenderSettings& settings);

    /// The last message, once the run is over: done, unless already sent.
    void finish();
    /// The last message, after an error: rank 0 reports it, naming this rank.
    void fail(const std::string& message);

private:
    void last_message(int tag, const std::vector<std::byte>& bytes);
    MpiWorld& world_;
    std::string identity_;
    bool finished_ = false;
};

}  // namespace rt::cluster
