// Rank 0 of a cluster run: hands out rows a few at a time to whichever rank asks (itself
// included), gathers the finished rows into the film, and reports progress once for the job.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "rt/cluster/mpi_world.h"
#include "rt/render/renderer.h"

namespace rt::cluster {

class Coordinator {
public:
    /// identity: what rank 0 renders (scene and switches); every rank must render the same.
    Coordinator(MpiWorld& world, std::string identity);

    /// Renders the window with every rank and returns the whole film, as render() would. The
    /// observer hears of every gathered row (progress, the window). Throws ClusterError naming
    /// the rank when one fails or renders another picture, or when this process is stopped.
    Film render(const Scene& scene, const Accelerator& accel, const RenderSettings& settings,
                RenderObserver& observer, RenderStatistics& statistics);

    /// After a run that rendered nothing (-r, -w, -doi): lets the other ranks end.
    void finish();
    /// Tells every rank still working to stop, and waits for each one's last message.
    void stop_everyone();

private:
    // Rows [first, first + count) counted from the window's bottom; count 0 when none are left.
    std::pair<int, int> take_rows();
    bool everyone_finished() const;

    MpiWorld& world_;
    std::string identity_;
    std::vector<char> finished_;  // per rank: its last message (kDone or kFailed) has come
    std::vector<char> stopped_;   // per rank: kStop was sent
    int next_row_ = 0;
    int rows_total_ = 0;
    int fixed_rows_ = 0;  // RT_CLUSTER_ROWS: rows per hand-out (0: chosen as the render goes)
    bool rendered_ = false;
};

}  // namespace rt::cluster
