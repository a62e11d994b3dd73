#include "rt/cluster/coordinator.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <thread>

#include "rt/app/input_digest.h"
#include "rt/app/interrupt.h"
#include "rt/cluster/cluster_error.h"
#include "rt/cluster/local_render.h"
#include "rt/cluster/protocol.h"
#include "rt/core/text.h"
#include "rt/render/ray_kinds.h"

#include <fmt/format.h>

namespace rt::cluster {

namespace {

// The rows a hand-out holds when RT_CLUSTER_ROWS is unset or not a positive number: rather many
// at first, fewer near the end, so that the last rows spread over every rank.
constexpr int kMaxRowsPerHandOut = 8;

int rows_from_environment() {
    const char* text = std::getenv("RT_CLUSTER_ROWS");  // NOLINT(concurrency-mt-unsafe)
    const std::optional<std::int64_t> n = text != nullptr ? parse_integer(text) : std::nullopt;
    return n && *n > 0 && *n <= 1000000 ? static_cast<int>(*n) : 0;
}

std::string window_text(const PixelRect& w) {
    return fmt::format("window {} {} {} {}", w.left, w.top, w.right, w.bottom);
}

void pause_briefly() {
    // MPI's blocking calls spin on a core; polling with a short sleep leaves it to the threads.
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

}  // namespace

Coordinator::Coordinator(MpiWorld& world, std::string identity)
    : world_(world),
      identity_(std::move(identity)),
      finished_(static_cast<std::size_t>(world.size()), 0),
      stopped_(static_cast<std::size_t>(world.size()), 0),
      fixed_rows_(rows_from_environment()) {
    finished_[0] = 1;  // rank 0 is this process
}

std::pair<int, int> Coordinator::take_rows() {
    const int left = rows_total_ - next_row_;
    const int guided = std::clamp(left / (4 * world_.size()), 1, kMaxRowsPerHandOut);
    const int count = std::min(left, fixed_rows_ > 0 ? fixed_rows_ : guided);
    const std::pair<int, int> rows{next_row_, std::max(count, 0)};
    next_row_ += rows.second;
    return rows;
}

bool Coordinator::everyone_finished() const {
    return std::all_of(finished_.begin(), finished_.end(), [](char f) { return f != 0; });
}

Film Coordinator::render(const Scene& scene, const Accelerator& accel,
                         const RenderSettings& settings, RenderObserver& observer,
                         RenderStatistics& statistics) {
    rendered_ = true;
    const PixelRect& w = settings.window;
    rows_total_ = w.height();
    next_row_ = 0;
    const std::string expected = identity_ + " " + window_text(w);
    const std::string expected_inputs = input_digest(scene);
    Film film(scene.view.width, scene.view.height, w);
    std::vector<char> gathered(static_cast<std::size_t>(rows_total_), 0);
    int rows_gathered = 0;
    std::uint64_t samples = 0;
    std::uint64_t unrepresentable = 0;
    KindCounters others_rays;  // the other ranks' rays, for -p
    std::string failure;
    const auto row_floats = static_cast<std::size_t>(w.width()) * 3;

    const auto gather = [&](int y, std::uint64_t row_samples, std::span<const float> pixels,
                            int from) {
        const bool inside = y >= w.top && y <= w.bottom;
        if (!inside || pixels.size() != row_floats ||
            gathered[static_cast<std::size_t>(y - w.top)] != 0) {
            failure =
                fmt::format("rank {} sent row {} twice, outside the window or cut short", from, y);
            return;
        }
        gathered[static_cast<std::size_t>(y - w.top)] = 1;
        std::copy(pixels.begin(), pixels.end(),
                  film.data().begin() + static_cast<std::ptrdiff_t>(
                                            static_cast<std::size_t>(y - w.top) * row_floats));
        ++rows_gathered;
        samples += row_samples;
        observer.row_done({y, rows_gathered, rows_total_, row_samples, pixels});
    };
    const auto handle = [&](const MpiWorld::Message& m) {
        Unpacker in(m.bytes);
        switch (m.tag) {
            case kHello: {
                // "ARGUMENTS window L T R B inputs DIGEST": the picture asked for, then what the
                // rank read to render it (a machine with other scene files would render another
                // picture with the same switches).
                const std::string hello = in.rest_as_text();
                const std::size_t at = hello.rfind(" inputs ");
                const std::string asked = hello.substr(0, at);
                const std::string inputs = at == std::string::npos
                                               ? ""
                                               : hello.substr(at + std::string(" inputs ").size());
                if (asked != expected) {
                    failure = fmt::format(
                        "rank {} renders another picture: '{}', where rank 0 "
                        "renders '{}'",
                        m.from, asked, expected);
                } else if (inputs != expected_inputs) {
                    failure = fmt::format(
                        "rank {} read other scene files (inputs {}, rank 0's {}): every machine "
                        "needs the same files",
                        m.from, inputs, expected_inputs);
                }
                break;
            }
            case kRequest: {
                const auto [first, count] = take_rows();
                world_.send(m.from, kWork,
                            Packer().put(std::int32_t{first}).put(std::int32_t{count}).bytes);
                break;
            }
            case kRow: {
                std::int32_t y = 0;
                std::uint64_t row_samples = 0;
                if (!in.get(y) || !in.get(row_samples)) {
                    failure = fmt::format("rank {} sent a broken row message", m.from);
                    break;
                }
                const std::span<const std::byte> rest = in.rest();
                gather(y, row_samples,
                       {reinterpret_cast<const float*>(rest.data()), rest.size() / sizeof(float)},
                       m.from);
                break;
            }
            case kDone: {
                std::uint64_t n = 0;
                KindCounters rays;
                if (in.get(n) && in.get(rays)) {
                    unrepresentable += n;
                    others_rays += rays;
                }
                finished_[static_cast<std::size_t>(m.from)] = 1;
                break;
            }
            case kFailed:
                finished_[static_cast<std::size_t>(m.from)] = 1;
                failure = fmt::format("rank {} failed: {}", m.from, in.rest_as_text());
                break;
            default:
                failure = fmt::format("rank {} sent an unknown message (tag {})", m.from, m.tag);
        }
    };

    LocalRender local(scene, accel, settings);
    while (failure.empty()) {
        if (observer.should_stop()) {
            const int signal = interrupt_signal();
            failure = signal != 0 ? fmt::format(
                                        "stopped by signal {} ({}) before every row was "
                                        "gathered; no picture was written (under mpirun, "
                                        "a rank that fails ends the job: mpirun's message "
                                        "names it)",
                                        signal, signal == 2 ? "Ctrl-C" : "from mpirun")
                                  : "stopped before every row was gathered (the window was "
                                    "closed); no picture was written";
            break;
        }
        bool busy = false;
        while (failure.empty()) {
            const std::optional<MpiWorld::Message> m = world_.poll();
            if (!m) {
                break;
            }
            busy = true;
            handle(*m);
        }
        if (!local.rows().closed() && local.rows().waiting() < local.threads()) {
            const auto [first, count] = take_rows();
            for (int i = first; i < first + count; ++i) {
                local.rows().push(w.bottom - i);
            }
            if (count == 0) {
                local.rows().close();
            }
            busy = true;
        }
        for (const FinishedRow& row : local.take_finished()) {
            gather(row.y, row.samples, row.pixels, 0);
            busy = true;
        }
        if (local.failed()) {
            (void)local.join();  // rethrows: rank 0's own rows will never come
        }
        if (rows_gathered == rows_total_ && everyone_finished() && local.done()) {
            break;
        }
        if (!busy) {
            pause_briefly();
        }
    }
    if (!failure.empty()) {
        local.stop();
        throw ClusterError(failure);
    }
    const RenderStatistics own = local.join();
    statistics.by_kind += own.by_kind;
    statistics.by_kind += others_rays;
    statistics.counters = statistics.by_kind.total();
    statistics.rows_done = rows_gathered;
    statistics.threads = own.threads;
    statistics.unrepresentable_samples = own.unrepresentable_samples + unrepresentable;
    film.set_first_finished_row(w.top);
    return film;
}

void Coordinator::finish() {
    if (!rendered_) {
        stop_everyone();
    }
}

void Coordinator::stop_everyone() {
    for (int rank = 1; rank < world_.size(); ++rank) {
        const auto r = static_cast<std::size_t>(rank);
        if (finished_[r] == 0 && stopped_[r] == 0) {
            world_.send(rank, kStop, {});
            stopped_[r] = 1;
        }
    }
    while (!everyone_finished()) {
        const std::optional<MpiWorld::Message> m = world_.poll();
        if (!m) {
            pause_briefly();
        } else if (m->tag == kDone || m->tag == kFailed) {
            finished_[static_cast<std::size_t>(m->from)] = 1;
        }
        // Requests and rows of a stopped render are dropped.
    }
}

}  // namespace rt::cluster
