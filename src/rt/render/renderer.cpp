#include "rt/render/renderer.h"

#include <algorithm>
#include <atomic>
#include <mutex>
#include <thread>
#include <vector>

#include "rt/render/camera.h"
#include "rt/render/ray_tracer.h"

namespace rt {

namespace {

// Everything the worker threads share.
struct RenderJob {
    const Scene& scene;
    const RenderSettings& settings;
    const Camera camera;
    const RayTracer tracer;
    RenderObserver& observer;
    Film& film;
    std::atomic<int> next_row_index{0};   // rows are handed out bottom first
    std::atomic<bool> stopping{false};
    std::mutex observer_mutex;            // guards the observer, finished and rows_done
    std::vector<char> finished;           // per window row
    int rows_done = 0;

    RenderJob(const Scene& s, const Accelerator& accel, const RenderSettings& rs,
              RenderObserver& o, Film& f)
        : scene(s),
          settings(rs),
          camera(Camera::from_view(s.view)),
          tracer(s, accel, rs.shading),
          observer(o),
          film(f),
          finished(static_cast<std::size_t>(rs.window.height()), 0) {}
};

// The pixel's value: the mean of an n x n grid of samples at the centres of its strata.
Rgb render_pixel(RenderJob& job, int x, int y, TraceCounters& counters) {
    const int nx = std::max(1, job.scene.view.sample_resolution_x);
    const int ny = std::max(1, job.scene.view.sample_resolution_y);
    Rgb sum;
    for (int j = 0; j < ny; ++j) {
        for (int i = 0; i < nx; ++i) {
            const double px = x + (i + 0.5) / nx;
            const double py = y + (j + 0.5) / ny;
            sum += job.tracer.trace(job.camera.primary_ray(px, py), 1, counters);
        }
    }
    return sum * (1.0 / (nx * ny));
}

void record_finished_row(RenderJob& job, int y) {
    const FilmWindow& w = job.settings.window;
    std::lock_guard lock(job.observer_mutex);
    job.finished[static_cast<std::size_t>(y - w.top)] = 1;
    ++job.rows_done;
    int first = job.film.first_finished_row();
    while (first > w.top && job.finished[static_cast<std::size_t>(first - 1 - w.top)] != 0) {
        --first;
    }
    job.film.set_first_finished_row(first);
    job.observer.row_done(y, job.rows_done, w.height());
    if (job.observer.should_stop()) {
        job.stopping = true;
    }
}

void render_rows(RenderJob& job, TraceCounters& counters) {
    const FilmWindow& w = job.settings.window;
    const bool pixel_events = job.observer.wants_pixel_events();
    while (!job.stopping) {
        const int index = job.next_row_index++;
        if (index >= w.height()) {
            return;
        }
        const int y = w.bottom - index;
        for (int x = w.left; x <= w.right; ++x) {
            if (pixel_events) {
                std::lock_guard lock(job.observer_mutex);
                job.observer.pixel_started(x, y);
            }
            job.film.set_pixel(x, y, render_pixel(job, x, y, counters));
        }
        record_finished_row(job, y);
    }
}

int thread_count(int requested, int rows) {
    int n = requested > 0 ? requested : static_cast<int>(std::thread::hardware_concurrency());
    return std::clamp(n, 1, std::max(1, rows));
}

}  // namespace

Film render(const Scene& scene, const Accelerator& accel, const RenderSettings& settings,
            RenderObserver& observer, RenderStatistics& statistics) {
    Film film(scene.view.width, scene.view.height, settings.window);
    RenderJob job(scene, accel, settings, observer, film);
    const int n = thread_count(settings.threads, settings.window.height());
    std::vector<TraceCounters> counters(static_cast<std::size_t>(n));
    std::vector<std::thread> workers;
    for (int i = 1; i < n; ++i) {
        workers.emplace_back(
            [&job, &counters, i] { render_rows(job, counters[static_cast<std::size_t>(i)]); });
    }
    render_rows(job, counters[0]);
    for (std::thread& t : workers) {
        t.join();
    }
    for (const TraceCounters& c : counters) {
        statistics.counters.rays += c.rays;
        statistics.counters.polygon_tests += c.polygon_tests;
        statistics.counters.hits += c.hits;
    }
    statistics.rows_done = job.rows_done;
    statistics.threads = n;
    statistics.interrupted = job.stopping && !film.complete();
    return film;
}

}  // namespace rt
