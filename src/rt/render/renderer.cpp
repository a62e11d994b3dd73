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
#include "rt/render/row_bands.h"
#include "rt/sampling/adaptive_mean.h"
#include "rt/sampling/chi_square.h"
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
    std::atomic<int> next_row_index{0};  // rows are handed out bottom first, in bands
    int threads = 1;
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

// A pixel's eye ray: its random numbers after the jitter within its stratum (the sample's tree
// draws on from there), and the ray. One sample per pixel looks through the pixel's centre, as
// the original did.
struct EyeSample {
    SampleStream stream{0, 0, 0, 0};
    Ray ray;
};

EyeSample eye_sample(const RenderJob& job, int x, int y, std::uint32_t k) {
    SampleStream stream(job.settings.shading.sampling.seed, x, y, k);
    double px = 0.5;
    double py = 0.5;
    if (job.pixel_strata.size() > 1) {
        const double j1 = stream.uniform();
        const double j2 = stream.uniform();
        job.pixel_strata.point(k, j1, j2, px, py);
    }
    return {stream, job.camera.primary_ray(x + px, y + py)};
}

// The feelers' answers eye_feelers keeps for each of `rays` eye rays: one a light, or none where
// a run of rays would need more than kMostFeelerAnswers (a scene of thousands of point lights,
// all samples of a run with -Dx): the room would grow past a few megabytes, and the feelers are
// asked one by one instead.
constexpr std::size_t kMostFeelerAnswers = std::size_t{1} << 15;

std::size_t feelers_to_plan(const RayTracer& tracer, std::size_t rays) {
    const std::size_t per_ray = tracer.eye_feelers_per_ray();
    return per_ray != 0 && rays <= kMostFeelerAnswers / per_ray ? per_ray : 0;
}

// The eye rays a run of neighbouring pixels takes whatever the adaptive rule decides (the first
// minimum_samples of each, or all with -Dx), found before the pixels are shaded so that they go
// through the accelerator eight at a time: samples of one pixel and of its neighbours are
// coherent rays. Each sample keeps its own random stream, so the picture is the same.
class FirstEyeRays {
public:
    static constexpr int kPixels = 8;  ///< pixels found at once

    explicit FirstEyeRays(const RenderJob& job)
        : per_pixel_(job.settings.shading.sampling.adaptive
                         ? minimum_samples(job.pixel_strata.size())
                         : job.pixel_strata.size()) {}

    /// Finds the first eye rays of pixels x0 to x1 (at most kPixels) of row y, and their
    /// feelers' first answers.
    void find(const RenderJob& job, int x0, int x1, int y, TraceCounters& eye_counters,
              TraceCounters& feeler_counters) {
        x0_ = x0;
        samples_.clear();
        rays_.clear();
        for (int x = x0; x <= x1; ++x) {
            for (std::uint32_t k = 0; k < per_pixel_; ++k) {
                samples_.push_back(eye_sample(job, x, y, k));
                rays_.push_back(samples_.back().ray);
            }
        }
        hits_.assign(rays_.size(), std::nullopt);
        job.tracer.eye_ray_hits(rays_, hits_, eye_counters);
        feelers_per_ray_ = feelers_to_plan(job.tracer, rays_.size());
        if (feelers_per_ray_ != 0) {
            feelers_.resize(rays_.size() * feelers_per_ray_);
            job.tracer.eye_feelers(rays_, hits_, feelers_, feeler_counters, feeler_room_);
        }
    }

    std::uint32_t per_pixel() const { return per_pixel_; }
    const EyeSample& sample(int x, std::uint32_t k) const { return samples_[index(x, k)]; }
    const std::optional<Hit>& hit(int x, std::uint32_t k) const { return hits_[index(x, k)]; }
    std::span<const FeelerAnswer> feelers(int x, std::uint32_t k) const {
        return std::span(feelers_).subspan(index(x, k) * feelers_per_ray_, feelers_per_ray_);
    }

private:
    std::size_t index(int x, std::uint32_t k) const {
        return static_cast<std::size_t>(x - x0_) * per_pixel_ + k;
    }

    std::uint32_t per_pixel_;
    int x0_ = 0;
    std::vector<EyeSample> samples_;
    std::vector<Ray> rays_;
    std::vector<std::optional<Hit>> hits_;
    std::size_t feelers_per_ray_ = 0;
    std::vector<FeelerAnswer> feelers_;  ///< feelers_per_ray_ a ray
    EyeFeelerRoom feeler_room_;
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
// neighbouring pixels, see the same surface. The first samples' hits are in `first`.
// Room for a pixel's samples found eight at a time once the rule cannot stop early: kept by
// the thread from pixel to pixel, as making its 1.4 kB afresh for every pixel cost about 2 % of
// twocubes4's render. A pixel reads only what it wrote.
struct EyeRaysAhead {
    std::array<EyeSample, kPacketSize> samples;
    std::array<Ray, kPacketSize> rays;
    std::array<std::optional<Hit>, kPacketSize> hits;
    std::vector<FeelerAnswer> feelers;  ///< feelers_to_plan(tracer, kPacketSize) a ray
    EyeFeelerRoom feeler_room;
};

Rgb render_pixel(RenderJob& job, int x, int y, const FirstEyeRays& first, EyeRaysAhead& room,
                 KindCounters& counters, PixelReport& report, CentreMemo* memo) {
    const SamplingSettings& sampling = job.settings.shading.sampling;
    const std::uint32_t total = job.pixel_strata.size();
    // Once the rule cannot stop early, the rest of the samples are found eight at a time too.
    std::array<EyeSample, kPacketSize>& ahead = room.samples;
    std::array<Ray, kPacketSize>& ahead_rays = room.rays;
    std::array<std::optional<Hit>, kPacketSize>& ahead_hits = room.hits;
    std::uint32_t ahead_first = 0;
    std::uint32_t ahead_count = 0;
    const std::size_t feelers_per_ray = feelers_to_plan(job.tracer, kPacketSize);
    const auto take = [&](std::uint32_t k, std::uint32_t certain) {
        if (k >= first.per_pixel() && certain - k > 1 && k - ahead_first >= ahead_count) {
            ahead_first = k;
            ahead_count = std::min<std::uint32_t>(kPacketSize, certain - k);
            for (std::uint32_t i = 0; i < ahead_count; ++i) {
                ahead[i] = eye_sample(job, x, y, k + i);
                ahead_rays[i] = ahead[i].ray;
            }
            job.tracer.eye_ray_hits(std::span(ahead_rays).first(ahead_count), ahead_hits,
                                    counters[RayKind::Eye]);
            if (feelers_per_ray != 0) {
                room.feelers.resize(ahead_count * feelers_per_ray);
                job.tracer.eye_feelers(std::span(ahead_rays).first(ahead_count),
                                       std::span(ahead_hits).first(ahead_count), room.feelers,
                                       counters[RayKind::ShadowFeeler], room.feeler_room);
            }
        }
        const bool found_first = k < first.per_pixel();
        const bool found_ahead = !found_first && k - ahead_first < ahead_count;
        EyeSample eye = found_first   ? first.sample(x, k)
                        : found_ahead ? ahead[k - ahead_first]
                                      : eye_sample(job, x, y, k);
        SampleContext sample{eye.stream, counters, report.tree, {}};
        if (found_first) {
            sample.eye_feelers = first.feelers(x, k);
        } else if (found_ahead && feelers_per_ray != 0) {
            sample.eye_feelers = std::span<const FeelerAnswer>(room.feelers)
                                     .subspan((k - ahead_first) * feelers_per_ray, feelers_per_ray);
        }
        Rgb value = found_first ? job.tracer.trace_eye_ray(eye.ray, first.hit(x, k), sample)
                    : found_ahead
                        ? job.tracer.trace_eye_ray(eye.ray, ahead_hits[k - ahead_first], sample)
                        : job.tracer.trace(eye.ray, RayKind::Eye, 1, false, sample);
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
    FirstEyeRays first(job);
    EyeRaysAhead ahead;
    RowBand band;
    while (!job.stopping) {
        int y = 0;
        if (job.settings.rows != nullptr) {
            const std::optional<int> row = job.settings.rows->next_row();
            if (!row) {
                return;
            }
            y = *row;
        } else {
            if (band.empty()) {
                band = claim_row_band(job.next_row_index, w.height(), job.threads);
                if (band.empty()) {
                    return;
                }
            }
            y = w.bottom - band.first++;
        }
        std::uint64_t samples = 0;
        for (int x = w.left; x <= w.right && !job.stop_now(); ++x) {
            if ((x - w.left) % FirstEyeRays::kPixels == 0) {
                first.find(job, x, std::min(w.right, x + FirstEyeRays::kPixels - 1), y,
                           counters[RayKind::Eye], counters[RayKind::ShadowFeeler]);
            }
            if (pixel_events) {
                std::lock_guard lock(job.observer_mutex);
                job.observer.pixel_started(x, y);
            }
            PixelReport report;
            job.film.set_pixel(
                x, y,
                render_pixel(job, x, y, first, ahead, counters, report, memo ? &*memo : nullptr));
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

std::uint64_t most_eye_rays(const Scene& scene, const RenderSettings& settings) {
    const std::uint64_t samples =
        ProgressiveStrata(scene.view.sample_resolution_x, scene.view.sample_resolution_y).size();
    const std::uint64_t per_pixel = samples + (samples > 1 ? 4 : 0);
    const PixelRect& w = settings.window;
    const auto pixels = static_cast<std::uint64_t>(std::max(w.width(), 0)) *
                        static_cast<std::uint64_t>(std::max(w.height(), 0));
    return pixels * per_pixel;
}

Film render(const Scene& scene, const Accelerator& accel, const RenderSettings& settings,
            RenderObserver& observer, RenderStatistics& statistics) {
    Film film(scene.view.width, scene.view.height, settings.window);
    RenderJob job(scene, accel, settings, observer, film);
    if (settings.resume != nullptr) {
        take_finished_rows(job, *settings.resume);
    }
    const int n = thread_count(settings.threads, settings.window.height());
    job.threads = n;
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
