#include "rt/accel/debug/query_recorder.h"

#include <bit>

namespace rt {

void QueryRecorder::record(QueryKind kind, const Ray& ray, Interval t) const {
    const std::lock_guard lock(mutex_);
    recorded_.queries.push_back({kind, 1, recorded_.rays.size()});
    recorded_.rays.push_back(ray);
    recorded_.t.push_back(t);
    ++recorded_.rays_asked;
}

void QueryRecorder::record(QueryKind kind, const RayPacket& packet) const {
    const std::lock_guard lock(mutex_);
    recorded_.queries.push_back({kind, packet.active, recorded_.rays.size()});
    recorded_.rays.insert(recorded_.rays.end(), packet.rays.begin(), packet.rays.end());
    recorded_.t.insert(recorded_.t.end(), packet.t.begin(), packet.t.end());
    recorded_.rays_asked += static_cast<std::uint64_t>(std::popcount(packet.active));
}

std::optional<Hit> QueryRecorder::closest_hit(const Ray& ray, Interval t,
                                              TraceCounters& counters) const {
    record(QueryKind::Closest, ray, t);
    return traced_.closest_hit(ray, t, counters);
}

std::optional<Hit> QueryRecorder::eye_ray_closest_hit(const Ray& ray, Interval t,
                                                      TraceCounters& counters) const {
    record(QueryKind::EyeClosest, ray, t);
    return traced_.eye_ray_closest_hit(ray, t, counters);
}

bool QueryRecorder::occluded(const Ray& ray, Interval t, TraceCounters& counters) const {
    record(QueryKind::Occluded, ray, t);
    return traced_.occluded(ray, t, counters);
}

void QueryRecorder::closest_hit_packet(const RayPacket& packet, PacketHits& hits,
                                       TraceCounters& counters) const {
    record(QueryKind::ClosestPacket, packet);
    traced_.closest_hit_packet(packet, hits, counters);
}

void QueryRecorder::eye_ray_closest_hit_packet(const RayPacket& packet, PacketHits& hits,
                                               TraceCounters& counters) const {
    record(QueryKind::EyeClosestPacket, packet);
    traced_.eye_ray_closest_hit_packet(packet, hits, counters);
}

std::uint32_t QueryRecorder::occluded_packet(const RayPacket& packet,
                                             TraceCounters& counters) const {
    record(QueryKind::OccludedPacket, packet);
    return traced_.occluded_packet(packet, counters);
}

RecordedQueries QueryRecorder::take() {
    const std::lock_guard lock(mutex_);
    RecordedQueries taken = std::move(recorded_);
    recorded_ = {};
    return taken;
}

namespace {

RayPacket packet_of(const RecordedQueries& recorded, const RecordedQuery& query) {
    RayPacket packet;
    for (std::size_t lane = 0; lane < kPacketSize; ++lane) {
        packet.rays[lane] = recorded.rays[query.first + lane];
        packet.t[lane] = recorded.t[query.first + lane];
    }
    packet.active = query.active;
    return packet;
}

// A single ray's query asked again; 1 if it found a hit or was blocked.
std::uint64_t replay_single(const RecordedQueries& recorded, std::size_t q,
                            const Accelerator& accel, TraceCounters& counters,
                            const ReplayAnswerSink& answer) {
    const RecordedQuery& query = recorded.queries[q];
    const Ray& ray = recorded.rays[query.first];
    const Interval t = recorded.t[query.first];
    if (query.kind == QueryKind::Occluded) {
        const bool blocked = accel.occluded(ray, t, counters);
        if (answer) {
            answer(q, 0, std::nullopt, blocked);
        }
        return blocked ? 1 : 0;
    }
    const std::optional<Hit> hit = query.kind == QueryKind::Closest
                                       ? accel.closest_hit(ray, t, counters)
                                       : accel.eye_ray_closest_hit(ray, t, counters);
    if (answer) {
        answer(q, 0, hit, false);
    }
    return hit ? 1 : 0;
}

// A packet's query asked again; its lanes that found a hit or were blocked.
std::uint64_t replay_packet(const RecordedQueries& recorded, std::size_t q,
                            const Accelerator& accel, TraceCounters& counters,
                            const ReplayAnswerSink& answer) {
    const RecordedQuery& query = recorded.queries[q];
    const RayPacket packet = packet_of(recorded, query);
    std::uint64_t found = 0;
    if (query.kind == QueryKind::OccludedPacket) {
        const std::uint32_t blocked = accel.occluded_packet(packet, counters);
        for (int lane = 0; lane < kPacketSize; ++lane) {
            if (answer && ((packet.active >> lane) & 1u) != 0) {
                answer(q, lane, std::nullopt, ((blocked >> lane) & 1u) != 0);
            }
        }
        return static_cast<std::uint64_t>(std::popcount(blocked));
    }
    PacketHits hits;
    if (query.kind == QueryKind::ClosestPacket) {
        accel.closest_hit_packet(packet, hits, counters);
    } else {
        accel.eye_ray_closest_hit_packet(packet, hits, counters);
    }
    for (int lane = 0; lane < kPacketSize; ++lane) {
        if (((packet.active >> lane) & 1u) != 0) {
            found += hits[lane] ? 1 : 0;
            if (answer) {
                answer(q, lane, hits[lane], false);
            }
        }
    }
    return found;
}

}  // namespace

std::uint64_t replay_queries(const RecordedQueries& recorded, std::size_t begin, std::size_t end,
                             const Accelerator& accel, TraceCounters& counters,
                             const ReplayAnswerSink& answer) {
    std::uint64_t found = 0;
    for (std::size_t q = begin; q < end; ++q) {
        const QueryKind kind = recorded.queries[q].kind;
        const bool packet = kind == QueryKind::ClosestPacket ||
                            kind == QueryKind::EyeClosestPacket ||
                            kind == QueryKind::OccludedPacket;
        found += packet ? replay_packet(recorded, q, accel, counters, answer)
                        : replay_single(recorded, q, accel, counters, answer);
    }
    return found;
}

}  // namespace rt
