#include "lab_measure.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <chrono>
#include <cmath>
#include <ctime>
#include <mutex>
#include <string>
#include <thread>

#include "rt/accel/bvh/bvh.h"
#include "rt/accel/make_accelerator.h"
#include "rt/accel/octree_depth_for.h"
#include "rt/core/error.h"
#include "rt/core/huge_pages.h"

#include <fmt/format.h>

#include "lab_rays.h"
#include <pthread.h>
#include <sched.h>

namespace rt::lab {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// The CPU time this thread has used: single-thread rates are taken from it, so that other
// programs sharing the cores do not count against the method being measured.
double thread_cpu_seconds() {
    timespec now{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
    return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

// Keeps the calling thread on one CPU while it lives, then gives it back the CPUs it had (--pin).
// CPUs need not be alike: on machines with performance and efficiency cores for good, and on a
// virtual machine for seconds at a time, when one CPU is slowed from outside
// (docs/lab/pinned-2026-12-06.md). Pinned, a series of one-thread runs stays on one kind of CPU.
class PinnedThread {
public:
    explicit PinnedThread(int cpu) {
        if (cpu == LabOptions::kNoPin) {
            return;
        }
        if (pthread_getaffinity_np(pthread_self(), sizeof before_, &before_) != 0) {
            throw Error("--pin: cannot read this thread's CPUs");
        }
        cpu_set_t one;
        CPU_ZERO(&one);
        CPU_SET(static_cast<std::size_t>(cpu), &one);
        if (pthread_setaffinity_np(pthread_self(), sizeof one, &one) != 0) {
            throw Error(fmt::format("--pin {}: this thread cannot be moved there", cpu));
        }
        pinned_ = true;
    }
    ~PinnedThread() {
        if (pinned_) {
            pthread_setaffinity_np(pthread_self(), sizeof before_, &before_);
        }
    }
    PinnedThread(const PinnedThread&) = delete;
    PinnedThread& operator=(const PinnedThread&) = delete;

private:
    cpu_set_t before_{};
    bool pinned_ = false;
};

// Every k-th ray, so that brute force spends at most its budget of polygon tests.
std::vector<Ray> subsample(const std::vector<Ray>& rays, std::size_t keep) {
    if (keep >= rays.size()) {
        return rays;
    }
    std::vector<Ray> kept;
    const double stride = static_cast<double>(rays.size()) / static_cast<double>(keep);
    for (std::size_t i = 0; i < keep; ++i) {
        kept.push_back(rays[static_cast<std::size_t>(static_cast<double>(i) * stride)]);
    }
    return kept;
}

// One pass over the rays on `threads` threads, which take chunks of 64 rays in turn.
TraceCounters trace_pass(const Accelerator& accel, const std::vector<Ray>& rays, unsigned threads) {
    constexpr std::size_t kChunk = 64;
    std::atomic<std::size_t> next{0};
    std::mutex sum_lock;
    TraceCounters sum;
    const auto work = [&] {
        TraceCounters counters;
        for (std::size_t begin = next.fetch_add(kChunk); begin < rays.size();
             begin = next.fetch_add(kChunk)) {
            const std::size_t end = std::min(rays.size(), begin + kChunk);
            for (std::size_t i = begin; i < end; ++i) {
                ++counters.rays;
                counters.hits += accel.closest_hit(rays[i], Interval{}, counters).has_value();
            }
        }
        const std::lock_guard<std::mutex> hold(sum_lock);
        sum += counters;
    };
    if (threads <= 1) {
        work();
    } else {
        std::vector<std::thread> pool;
        for (unsigned t = 0; t < threads; ++t) {
            pool.emplace_back(work);
        }
        for (std::thread& t : pool) {
            t.join();
        }
    }
    return sum;
}

// One pass over the packets on this thread.
TraceCounters trace_packets(const Accelerator& accel, const std::vector<RayPacket>& packets) {
    TraceCounters counters;
    PacketHits hits;
    for (const RayPacket& packet : packets) {
        accel.closest_hit_packet(packet, hits, counters);
        counters.rays += static_cast<unsigned>(std::popcount(packet.active));
        for (int lane = 0; lane < kPacketSize; ++lane) {
            counters.hits += ((packet.active >> lane) & 1u) != 0 && hits[lane].has_value();
        }
    }
    return counters;
}

// As time_tracing on one thread, for packets.
TraceRate time_packet_tracing(const Accelerator& accel, const std::vector<RayPacket>& packets,
                              std::size_t rays, double least_seconds) {
    TraceRate rate;
    rate.rays = rays;
    if (packets.empty()) {
        return rate;
    }
    double total = 0.0;
    double fastest = HUGE_VAL;
    do {
        const double cpu_start = thread_cpu_seconds();
        const TraceCounters counters = trace_packets(accel, packets);
        const double elapsed = thread_cpu_seconds() - cpu_start;
        rate.hits = counters.hits;
        rate.nodes_per_ray =
            static_cast<double>(counters.nodes_visited) / static_cast<double>(rays);
        rate.tests_per_ray =
            static_cast<double>(counters.polygon_tests) / static_cast<double>(rays);
        fastest = std::min(fastest, elapsed);
        total += elapsed;
    } while (total < least_seconds);
    rate.mrays_per_second = static_cast<double>(rays) / fastest * 1e-6;
    return rate;
}

TraceRate time_tracing(const Accelerator& accel, const std::vector<Ray>& rays, unsigned threads,
                       double least_seconds, bool subsampled) {
    TraceRate rate;
    rate.rays = rays.size();
    rate.subsampled = subsampled;
    if (rays.empty()) {
        return rate;
    }
    // Passes repeat until `least_seconds` have gone by; the rate is the fastest pass's. The
    // machines we measure on are shared, and another tenant's load only ever slows a pass down,
    // so the fastest one is the truest figure (and the one that repeats best from run to run).
    double total = 0.0;
    double fastest = HUGE_VAL;
    do {
        const Clock::time_point start = Clock::now();
        const double cpu_start = thread_cpu_seconds();
        const TraceCounters counters = trace_pass(accel, rays, threads);
        const double elapsed =
            threads <= 1 ? thread_cpu_seconds() - cpu_start : seconds_since(start);
        rate.hits = counters.hits;
        rate.nodes_per_ray =
            static_cast<double>(counters.nodes_visited) / static_cast<double>(rays.size());
        rate.tests_per_ray =
            static_cast<double>(counters.polygon_tests) / static_cast<double>(rays.size());
        fastest = std::min(fastest, elapsed);
        total += elapsed;
    } while (total < least_seconds);
    rate.mrays_per_second = static_cast<double>(rays.size()) / fastest * 1e-6;
    return rate;
}

// Touches and frees room for a build of `triangles` (generously: 256 bytes a triangle, at most
// 4 GiB), in huge pages as the methods' big arrays are, so that every timed build finds memory the
// machine has backed already, whatever was built before it in the process. On a virtual machine
// memory the guest has not touched for a while costs far more to touch than memory it has just
// freed, and the method built first paid for that alone: the 1M sphere's BVH took 1.0 to 1.15
// times Embree's time when built first, 0.68 to 0.78 when second
// (docs/lab/bvh-build-order-2026-12-04.md).
void warm_memory(std::uint64_t triangles) {
    constexpr std::uint64_t kBytesPerTriangle = 256;
    constexpr std::uint64_t kMostBytes = std::uint64_t{4} << 30;
    const auto bytes =
        static_cast<std::size_t>(std::min(triangles * kBytesPerTriangle, kMostBytes));
    if (bytes < kHugeAllocation) {
        return;
    }
    HugePageAllocator<char> allocator;
    char* room = allocator.allocate(bytes);
    for (std::size_t at = 0; at < bytes; at += 4096) {
        room[at] = 1;
    }
    // The compiler may not drop the stores: the room is read back (one byte) before it is freed.
    volatile char sink = room[bytes / 2];
    static_cast<void>(sink);
    allocator.deallocate(room, bytes);
}

}  // namespace

std::uint64_t fan_triangles(const Scene& scene) {
    std::uint64_t count = 0;
    for (const Polygon& p : scene.polygons) {
        count += p.corner_count >= 3 ? p.corner_count - 2 : 0;
    }
    return count;
}

std::optional<Measurement> measure(const Scene& scene, const std::string& mesh, AccelKind kind,
                                   const LabRays& rays, const LabOptions& options) {
    AccelSettings settings;
    settings.kind = kind;
    settings.seads_resolution = options.seads_side != 0
                                    ? options.seads_side
                                    : suggested_seads_resolution(scene.polygons.size());
    settings.octree.depth =
        options.octree_depth != 0 ? options.octree_depth : octree_depth_for(scene);
    Measurement m;
    m.mesh = mesh;
    m.triangles = fan_triangles(scene);
    m.accel = std::string(accel_kind_name(kind));
    m.threads =
        options.threads != 0 ? options.threads : std::max(1u, std::thread::hardware_concurrency());
    std::unique_ptr<Accelerator> accel;
    warm_memory(m.triangles);
    const Clock::time_point start = Clock::now();
    try {
        accel = make_accelerator(scene, settings);
    } catch (const NotImplementedError&) {
        return std::nullopt;
    }
    m.build_ms = seconds_since(start) * 1e3;
    m.bytes_per_triangle = static_cast<double>(accel->memory_bytes()) /
                           static_cast<double>(std::max<std::uint64_t>(m.triangles, 1));
    if (const auto* tree = dynamic_cast<const Bvh*>(accel.get())) {
        m.tree_cost = tree->tree_cost();
    }

    const bool brute = kind == AccelKind::BruteForce;
    const auto budget = static_cast<std::size_t>(
        options.brute_force_tests / static_cast<double>(std::max<std::uint64_t>(m.triangles, 1)));
    const std::size_t keep = brute ? std::max<std::size_t>(budget, 16) : rays.primary.size();
    const std::vector<Ray> primary = subsample(rays.primary, keep);
    const std::vector<Ray> random = subsample(rays.random, keep);
    const bool primary_cut = primary.size() < rays.primary.size();
    const bool random_cut = random.size() < rays.random.size();
    const double least = options.seconds_per_run;
    {
        const PinnedThread pinned(options.pin_cpu);
        m.primary_one = time_tracing(*accel, primary, 1, least, primary_cut);
        m.random_one = time_tracing(*accel, random, 1, least, random_cut);
        if (options.pin_cpu != LabOptions::kNoPin) {
            m.pinned_cpu = sched_getcpu();
        }
    }
    m.primary_all = time_tracing(*accel, primary, m.threads, least, primary_cut);
    m.random_all = time_tracing(*accel, random, m.threads, least, random_cut);
    if (!brute) {
        const std::vector<RayPacket> primary_packets = packets_of(primary, kImageWidth);
        const std::vector<RayPacket> random_packets = packets_of(random, 0);
        const PinnedThread pinned(options.pin_cpu);
        m.primary_packet_one = time_packet_tracing(*accel, primary_packets, primary.size(), least);
        m.random_packet_one = time_packet_tracing(*accel, random_packets, random.size(), least);
    }
    return m;
}

}  // namespace rt::lab
