// Renders the output window line by line from the bottom up, as the original drew them, on
// several threads; every pixel is computed by one thread only, so the picture does not depend on
// the thread count.
#pragma once

#include "rt/accel/accelerator.h"
#include "rt/image/film.h"
#include "rt/scene/scene.h"
#include "rt/shading/shading_settings.h"

namespace rt {

struct RenderSettings {
    ShadingSettings shading;
    FilmWindow window;   ///< the part of the view area to render (output matrix, -L)
    int threads = 0;     ///< 0: one per core
};

/// Told about progress; asked whether to stop (Ctrl-C). Called from worker threads, but never
/// concurrently: the renderer serialises the calls.
class RenderObserver {
public:
    virtual ~RenderObserver() = default;
    /// Row y is finished; rows_done of rows_total are.
    virtual void row_done(int y, int rows_done, int rows_total) {
        (void)y;
        (void)rows_done;
        (void)rows_total;
    }
    /// The pixel (x, y) is about to be sampled (-dc).
    virtual void pixel_started(int x, int y) {
        (void)x;
        (void)y;
    }
    virtual bool wants_pixel_events() const { return false; }
    virtual bool should_stop() { return false; }
};

struct RenderStatistics {
    TraceCounters counters;
    int rows_done = 0;
    int threads = 0;  ///< worker threads the render used (settings.threads resolved)
    bool interrupted = false;
};

/// Renders the window into a new film. If the observer asks to stop, the rows finished so far
/// (a contiguous run from the bottom) are kept and the film says where they begin.
Film render(const Scene& scene, const Accelerator& accel, const RenderSettings& settings,
            RenderObserver& observer, RenderStatistics& statistics);

}  // namespace rt
