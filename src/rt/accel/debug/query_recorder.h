// The intersection queries a render asks, kept so that they can be asked again of any method away
// from the renderer: rt_scene_bench --replay times the methods on rt's own rays (eye rays, glossy
// reflections from surfaces, shadow feelers), which are not the lab's generated ones, and the
// tests compare every method's answers on them with brute force's.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <string_view>
#include <vector>

#include "rt/accel/accelerator.h"

namespace rt {

/// Which Accelerator call a query was: a single ray's or a packet's, for the nearest hit (an eye
/// ray's, or any other) or for any blocking hit.
enum class QueryKind : std::uint8_t {
    Closest,
    EyeClosest,
    Occluded,
    ClosestPacket,
    EyeClosestPacket,
    OccludedPacket,
};

struct RecordedQuery {
    QueryKind kind = QueryKind::Closest;
    std::uint32_t active = 1;  ///< a packet's lanes asked; 1 for a single ray
    std::size_t first = 0;     ///< into RecordedQueries::rays and ::t; a packet's lanes follow
};

struct RecordedQueries {
    std::vector<RecordedQuery> queries;
    std::vector<Ray> rays;         ///< a single query's ray, or a packet's kPacketSize lanes
    std::vector<Interval> t;       ///< the same way
    std::uint64_t rays_asked = 0;  ///< single rays and packets' active lanes
};

/// Passes every query on to the method beneath, unchanged, and keeps a copy of it in the order
/// asked. Safe from several threads (the order is then the threads' interleaving); a recording
/// render runs on one, so that the order is the render's own.
class QueryRecorder : public Accelerator {
public:
    /// `traced` must outlive the recorder.
    explicit QueryRecorder(const Accelerator& traced) : traced_(traced) {}
    std::string_view name() const override { return traced_.name(); }
    std::optional<Hit> closest_hit(const Ray& ray, Interval t,
                                   TraceCounters& counters) const override;
    std::optional<Hit> eye_ray_closest_hit(const Ray& ray, Interval t,
                                           TraceCounters& counters) const override;
    bool occluded(const Ray& ray, Interval t, TraceCounters& counters) const override;
    void closest_hit_packet(const RayPacket& packet, PacketHits& hits,
                            TraceCounters& counters) const override;
    void eye_ray_closest_hit_packet(const RayPacket& packet, PacketHits& hits,
                                    TraceCounters& counters) const override;
    std::uint32_t occluded_packet(const RayPacket& packet, TraceCounters& counters) const override;
    bool walks_packets() const override { return traced_.walks_packets(); }
    std::size_t memory_bytes() const override { return traced_.memory_bytes(); }

    /// What was recorded so far; the recorder starts again empty.
    RecordedQueries take();

private:
    void record(QueryKind kind, const Ray& ray, Interval t) const;
    void record(QueryKind kind, const RayPacket& packet) const;

    const Accelerator& traced_;
    mutable std::mutex mutex_;
    mutable RecordedQueries recorded_;
};

/// One ray's answer in a replay: `query` and `lane` (0 for a single ray) say which ray; `hit` is
/// a nearest-hit query's answer, `blocked` an occluded one's.
using ReplayAnswerSink =
    std::function<void(std::size_t query, int lane, const std::optional<Hit>& hit, bool blocked)>;

/// Asks queries [begin, end) of `accel` again, in order, with the calls they were asked with.
/// `answer`, when set, receives every ray's answer. Returns the hits and blocked rays counted,
/// which also keeps the calls from being optimised away when nothing is told of the answers.
std::uint64_t replay_queries(const RecordedQueries& recorded, std::size_t begin, std::size_t end,
                             const Accelerator& accel, TraceCounters& counters,
                             const ReplayAnswerSink& answer = {});

}  // namespace rt
