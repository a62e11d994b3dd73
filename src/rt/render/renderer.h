// Renders the output window line by line from the bottom up, as the original drew them, on
// several threads; every pixel is computed by one thread only, so the picture does not depend on
// the thread count.
#pragma once

#include <atomic>
#include <cstdint>
#include <optional>
#include <span>

#include "rt/accel/accelerator.h"
#include "rt/image/film.h"
#include "rt/render/ray_tracer.h"
#include "rt/scene/scene.h"
#include "rt/shading/shading_settings.h"

namespace rt {

/// Hands out the rows to render, one at a time, to the worker threads. Without one, the renderer
/// takes every window row from the bottom up; a cluster run (src/rt/cluster) feeds each process
/// the rows its coordinator hands it.
class RowSource {
public:
    virtual ~RowSource() = default;
    /// The next row (a view row inside the window), or nothing when there are no more. May block
    /// until one comes; called from several worker threads at once.
    virtual std::optional<int> next_row() = 0;
};

struct RenderSettings {
    ShadingSettings shading;
    PixelRect window;  ///< the part of the view area to render (output matrix, -L)
    int threads = 0;   ///< 0: one per core
    /// Null: every window row. A pixel's samples depend only on its coordinates and the seed, so
    /// a row renders the same whichever process or thread takes it.
    RowSource* rows = nullptr;
    /// Set from elsewhere (a signal handler) to stop at once: the ray trees in progress are cut
    /// short and their rows abandoned, the finished rows kept. May be null.
    const std::atomic<bool>* stop_now = nullptr;
    /// An interrupted render of the same scene and settings (--resume): its finished rows are
    /// taken as they are and only the rest are rendered. May be null.
    const Film* resume = nullptr;
};

/// How a pixel was sampled (-dx).
struct PixelReport {
    std::uint32_t samples = 0;  ///< eye rays taken (at most n x n)
    std::uint32_t probes = 0;   ///< rays through neighbouring pixels' centres (feelers only)
    RayTreeCounts tree;         ///< summed over its samples
};

/// A row just finished, as the observer hears of it.
struct RowDone {
    int y = 0;
    int rows_done = 0;  ///< rows finished so far, this one included
    int rows_total = 0;
    std::uint64_t samples = 0;  ///< eye rays (pixel samples) this row took
    /// The row's finished pixels, the window's width of them from its left edge, three linear
    /// floats each (a window shows them); valid during the call.
    std::span<const float> pixels;
};

/// Told about progress; asked whether to stop (Ctrl-C). Called from worker threads, but never
/// concurrently: the renderer serialises the calls.
class RenderObserver {
public:
    virtual ~RenderObserver() = default;
    virtual void row_done(const RowDone& row) { (void)row; }
    /// The pixel (x, y) is about to be sampled (-dc).
    virtual void pixel_started(int x, int y) {
        (void)x;
        (void)y;
    }
    virtual bool wants_pixel_events() const { return false; }
    /// The pixel (x, y) is done (-dx); only called when wants_sample_reports().
    virtual void pixel_sampled(int x, int y, const PixelReport& report) {
        (void)x;
        (void)y;
        (void)report;
    }
    virtual bool wants_sample_reports() const { return false; }
    virtual bool should_stop() { return false; }
};

struct RenderStatistics {
    KindCounters by_kind;
    TraceCounters counters;  ///< all kinds together
    int rows_done = 0;
    int threads = 0;  ///< worker threads the render used (settings.threads resolved)
    bool interrupted = false;
    /// Samples whose intensity was not a number or beyond the float range: counted as black.
    std::uint64_t unrepresentable_samples = 0;
};

/// The most rays render() sends from the eye for this scene and settings: each pixel of the
/// window takes at most its n x n samples, and with more than one it may probe its four
/// neighbours' centres once (the adaptive rule's check). Exit culling is worth building only for
/// scenes of fewer polygons than that (AcceleratorStackSettings::most_eye_rays).
std::uint64_t most_eye_rays(const Scene& scene, const RenderSettings& settings);

/// Renders the window into a new film. If the observer asks to stop, or settings.stop_now is set,
/// the rows finished so far (a contiguous run from the bottom) are kept and the film says where
/// they begin.
Film render(const Scene& scene, const Accelerator& accel, const RenderSettings& settings,
            RenderObserver& observer, RenderStatistics& statistics);

}  // namespace rt
