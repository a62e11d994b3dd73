#include "rt/render/renderer.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cfloat>
#include <cmath>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "rt/geometry/camera.h"
#include "rt/render/ray_tracer.h"
#include "rt/sampling/adaptive_mean.h"
#include "rt/sampling/sample_stream.h"
#include "rt/sampling/sampling_settings.h"
#include "rt/sampling/strata.h"

namespace rt {

namespace {

// Everything the worker threads share.
struct RenderJob {
    const Scene& scene;
    const RenderSettings& settings;
    const Camera camera;
    RayTracer tracer;
    const ProgressiveStrata pixel_strata;
    RenderObserver& observer;
    Film& film;
    std::atomic<int> next_row_index{0};  // rows are handed out bottom first
    std::atomic<bool> stopping{false};
    std::atomic<std::uint64_t> unrepresentable_samples{0};
    std::mutex observer_mutex;   // guards the observer, finished and rows_done
    std::vector<char> finished;  // per window row
    int rows_done = 0;

    RenderJob(const Scene& s, const Accelerator& accel, const RenderSettings& rs, RenderObserver& o,
              Film& f)
        : scene(s),
          settings(rs),
          camera(s.view.camera()),
          tracer(s, accel, rs.shading),
          pixel_strata(s.view.sample_resolution_x, s.view.sample_resolution_y),
          observer(o),
          film(f),
          finished(static_cast<std::size_t>(rs.window.height()), 0) {
        tracer.abandon_when(rs.stop_now);
    }

    /// Whether the render must stop at once (Ctrl-C): what is being traced is worthless.
    bool stop_now() const {
        return settings.stop_now != nullptr && settings.stop_now->load(std::memory_order_relaxed);
    }
};

// Whether every channel is a number the film's floats can hold.
bool representable(const Rgb& c) {
    return std::fabs(c.r) <= FLT_MAX && std::fabs(c.g) <= FLT_MAX && std::fabs(c.b) <= FLT_MAX;
}

// What the rays through pixel centres saw, kept for the rows around the one a thread renders:
// the adaptive rule asks each centre for up to four neighbouring pixels. Without fuzzy feelers
// (the only random numbers a probe draws) a centre's answer depends on the pixel alone, so it is
// traced once per visit instead of once per asking neighbour; the picture is the same. A kept
// answer adds the counters of its rays again, so that -p's table stays what the rule asked for,
// the same whichever thread or process renders which rows.
struct CentreSeen {
    SurfaceSeen seen;
    TraceCounters probe;    ///< the centre ray's counters
    TraceCounters feelers;  ///< its hit's shadow feelers'
};

class CentreMemo {
public:
    explicit CentreMemo(int view_width) {
        for (Row& row : rows_) {
            row.seen.resize(static_cast<std::size_t>(view_width));
        }
    }

    std::optional<CentreSeen>& at(int x, int y) {
        Row& row = rows_[static_cast<std::size_t>(y) % rows_.size()];  // y-1, y, y+1 differ
        if (row.y != y) {
            row.y = y;
            std::fill(row.seen.begin(), row.seen.end(), std::nullopt);
        }
        return row.seen[static_cast<std::size_t>(x)];
    }

private:
    struct Row {
        int y = -1;
        std::vector<std::optional<CentreSeen>> seen;
    };
    std::array<Row, 4> rows_;
};

// Whether the centre rays of the four neighbouring pixels see the same surface (SurfaceSeen: one
// polygon in the same light, or all miss): a polygon's edge or a shadow's edge can pass between
// a pixel's first samples unseen, but rarely past its neighbours too. `memo` is null when the
// answers may not be kept (fuzzy feelers).
bool neighbours_see(RenderJob& job, int x, int y, const SurfaceSeen& seen, SampleContext& probe,
                    CentreMemo* memo) {
    const int offsets[4][2] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};
    for (const auto& offset : offsets) {
        const int nx = std::clamp(x + offset[0], 0, job.scene.view.width - 1);
        const int ny = std::clamp(y + offset[1], 0, job.scene.view.height - 1);
        const auto ray_of_centre = [&] { return job.camera.primary_ray(nx + 0.5, ny + 0.5); };
        SurfaceSeen centre;
        if (memo == nullptr) {
            centre = job.tracer.first_surface(ray_of_centre(), RayStart::Eye, true, probe);
        } else {
            std::optional<CentreSeen>& kept = memo->at(nx, ny);
            if (!kept) {
                KindCounters own;
                SampleContext traced{probe.stream, own, probe.tree, {}};
                kept = CentreSeen{
                    job.tracer.first_surface(ray_of_centre(), RayStart::Eye, true, traced),
                    own[RayKind::Probe], own[RayKind::ShadowFeeler]};
            }
            probe.counters[RayKind::Probe] += kept->probe;
            probe.counters[RayKind::ShadowFeeler] += kept->feelers;
            centre = kept->seen;
        }
        if (!(centre == seen)) {
            return false;
        }
    }
    return true;
}

// The pixel's value: the mean of up to n x n samples (manual 2.2), jittered in their strata
// and taken in progressive order until the chi-square rule (-Xp) is satisfied, or all of them
// with -Dx. The rule may stop early only where every sample so far, and the centres of the four
// neighbouring pixels, see the same surface. One sample per pixel looks through the pixel's
// centre, as the original did.
Rgb render_pixel(RenderJob& job, int x, int y, KindCounters& counters, PixelReport& report,
                 CentreMemo* memo) {
    const SamplingSettings& sampling = job.settings.shading.sampling;
    const std::uint32_t total = job.pixel_strata.size();
    const auto take = [&](std::uint32_t k) {
        SampleStream stream(sampling.seed, x, y, k);
        double px = 0.5;
        double py = 0.5;
        if (total > 1) {
            const double j1 = stream.uniform();
            const double j2 = stream.uniform();
            job.pixel_strata.point(k, j1, j2, px, py);
        }
        SampleContext sample{stream, counters, report.tree, {}};
        Rgb value = job.tracer.trace(job.camera.primary_ray(x + px, y + py), RayKind::Eye, 1, false,
                                     sample);
        // An intensity beyond the float range (or not a number) would spoil the pixel and the
        // outputs: the sample counts as black, and the run says how many there were.
        if (!representable(value)) {
            ++job.unrepresentable_samples;
            value = Rgb{};
        }
        return SeenSample<SurfaceSeen>{value, sample.last_seen};
    };
    const auto neighbours_agree = [&](const SurfaceSeen& seen) {
        SampleStream probe_stream(sampling.seed, x, y, total);  // after the pixel's samples
        SampleContext probe{probe_stream, counters, report.tree, {}};
        report.probes += 4;
        return neighbours_see(job, x, y, seen, probe, memo);
    };
    const RunningStatistics statistics = adaptive_mean(
        total, sampling.adaptive ? &sampling.pixel_stop : nullptr, take, neighbours_agree);
    report.samples = statistics.count();
    const Rgb mean = statistics.mean();
    if (!representable(mean)) {  // finite samples whose sum overflows
        job.unrepresentable_samples += statistics.count();
        return Rgb{};
    }
    return mean;
}

void record_finished_row(RenderJob& job, int y, std::uint64_t samples) {
    const PixelRect& w = job.settings.window;
    std::lock_guard lock(job.observer_mutex);
    job.finished[static_cast<std::size_t>(y - w.top)] = 1;
    ++job.rows_done;
    int first = job.film.first_finished_row();
    while (first > w.top && job.finished[static_cast<std::size_t>(first - 1 - w.top)] != 0) {
        --first;
    }
    job.film.set_first_finished_row(first);
    const auto row_floats = static_cast<std::size_t>(w.width()) * 3;
    const std::span<const float> pixels =
        std::span<const float>(job.film.data())
            .subspan(static_cast<std::size_t>(y - w.top) * row_floats, row_floats);
    job.observer.row_done({y, job.rows_done, w.height(), samples, pixels});
    if (job.observer.should_stop()) {
        job.stopping = true;
    }
}

void render_rows(RenderJob& job, KindCounters& counters) {
    const PixelRect& w = job.settings.window;
    const bool pixel_events = job.observer.wants_pixel_events();
    const bool sample_events = job.observer.wants_sample_reports();
    std::optional<CentreMemo> memo;
    if (!job.settings.shading.fuzzy.enabled()) {
        memo.emplace(job.scene.view.width);
    }
    while (!job.stopping) {
        int y = 0;
        if (job.settings.rows != nullptr) {
            const std::optional<int> row = job.settings.rows->next_row();
            if (!row) {
                return;
            }
            y = *row;
        } else {
            const int index = job.next_row_index++;
            if (index >= w.height()) {
                return;
            }
            y = w.bottom - index;
        }
        std::uint64_t samples = 0;
        for (int x = w.left; x <= w.right && !job.stop_now(); ++x) {
            if (pixel_events) {
                std::lock_guard lock(job.observer_mutex);
                job.observer.pixel_started(x, y);
            }
            PixelReport report;
            job.film.set_pixel(x, y,
                               render_pixel(job, x, y, counters, report, memo ? &*memo : nullptr));
            samples += report.samples;
            if (sample_events) {
                std::lock_guard lock(job.observer_mutex);
                job.observer.pixel_sampled(x, y, report);
            }
        }
        if (job.stop_now()) {
            // Some of the row's rays may have been cut short: the row is abandoned, black as it
            // was, and the rows above it are never started.
            for (int x = w.left; x <= w.right; ++x) {
                job.film.set_pixel(x, y, {});
            }
            job.stopping = true;
            return;
        }
        record_finished_row(job, y, samples);
    }
}

int thread_count(int requested, int rows) {
    int n = requested > 0 ? requested : static_cast<int>(std::thread::hardware_concurrency());
    return std::clamp(n, 1, std::max(1, rows));
}

// The finished rows of an interrupted render, taken over: its rows from the bottom to its first
// finished row, which the workers then skip. Every pixel depends only on the seed and its place,
// so the rest rendered now completes the same picture.
void take_finished_rows(RenderJob& job, const Film& done) {
    const PixelRect& w = job.settings.window;
    const int first = std::clamp(done.first_finished_row(), w.top, w.bottom + 1);
    const auto row_floats = static_cast<std::ptrdiff_t>(w.width()) * 3;
    const auto from_row = static_cast<std::ptrdiff_t>(first - w.top);
    std::copy(done.data().begin() + from_row * row_floats, done.data().end(),
              job.film.data().begin() + from_row * row_floats);
    for (int y = first; y <= w.bottom; ++y) {
        job.finished[static_cast<std::size_t>(y - w.top)] = 1;
    }
    job.rows_done = w.bottom + 1 - first;
    job.next_row_index = job.rows_done;
    job.film.set_first_finished_row(first);
}

}  // namespace

Film render(const Scene& scene, const Accelerator& accel, const RenderSettings& settings,
            RenderObserver& observer, RenderStatistics& statistics) {
    Film film(scene.view.width, scene.view.height, settings.window);
    RenderJob job(scene, accel, settings, observer, film);
    if (settings.resume != nullptr) {
        take_finished_rows(job, *settings.resume);
    }
    const int n = thread_count(settings.threads, settings.window.height());
    std::vector<KindCounters> counters(static_cast<std::size_t>(n));
    std::vector<std::thread> workers;
    for (int i = 1; i < n; ++i) {
        workers.emplace_back(
            [&job, &counters, i] { render_rows(job, counters[static_cast<std::size_t>(i)]); });
    }
    render_rows(job, counters[0]);
    for (std::thread& t : workers) {
        t.join();
    }
    for (const KindCounters& c : counters) {
        statistics.by_kind += c;
    }
    statistics.counters = statistics.by_kind.total();
    statistics.rows_done = job.rows_done;
    statistics.threads = n;
    statistics.interrupted = job.stopping && !film.complete();
    statistics.unrepresentable_samples = job.unrepresentable_samples;
    return film;
}

}  // namespace rt
