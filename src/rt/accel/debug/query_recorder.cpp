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

}  // namespace

std::uint64_t replay_queries(const RecordedQueries& recorded, std::size_t begin, std::size_t end,
                             const Accelerator& accel, TraceCounters& counters,
                             const ReplayAnswerSink& answer) {
    std::uint64_t found = 0;
    for (std::size_t q = begin; q < end; ++q) {
        const RecordedQuery& query = recorded.queries[q];
        const Ray& ray = recorded.rays[query.first];
        const Interval t = recorded.t[query.first];
        switch (query.kind) {
            case QueryKind::Closest:
            case QueryKind::EyeClosest: {
                const std::optional<Hit> hit = query.kind == QueryKind::Closest
                                                   ? accel.closest_hit(ray, t, counters)
                                                   : accel.eye_ray_closest_hit(ray, t, counters);
                found += hit ? 1 : 0;
                if (answer) {
                    answer(q, 0, hit, false);
                }
                break;
            }
            case QueryKind::Occluded: {
                const bool blocked = accel.occluded(ray, t, counters);
                found += blocked ? 1 : 0;
                if (answer) {
                    answer(q, 0, std::nullopt, blocked);
                }
                break;
            }
            case QueryKind::ClosestPacket:
            case QueryKind::EyeClosestPacket: {
                const RayPacket packet = packet_of(recorded, query);
                PacketHits hits;
                if (query.kind == QueryKind::ClosestPacket) {
                    accel.closest_hit_packet(packet, hits, counters);
                } else {
                    accel.eye_ray_closest_hit_packet(packet, hits, counters);
                }
                for (int lane = 0; lane < kPacketSize; ++lane) {
                    if ((packet.active >> lane) & 1u) {
                        found += hits[lane] ? 1 : 0;
                        if (answer) {
                            answer(q, lane, hits[lane], false);
                        }
                    }
                }
                break;
            }
            case QueryKind::OccludedPacket: {
                const RayPacket packet = packet_of(recorded, query);
                const std::uint32_t blocked = accel.occluded_packet(packet, counters);
                found += static_cast<std::uint64_t>(std::popcount(blocked));
                if (answer) {
                    for (int lane = 0; lane < kPacketSize; ++lane) {
                        if ((packet.active >> lane) & 1u) {
                            answer(q, lane, std::nullopt, ((blocked >> lane) & 1u) != 0);
                        }
                    }
                }
                break;
            }
        }
    }
    return found;
}

}  // namespace rt
