// The shadow feelers from eye hits, eight at a time (issue 15): rays of neighbouring samples hit
// neighbouring points, and their feelers toward one light point are coherent, as the eye rays
// were. Each feeler is planned by the steps shading takes (light_side, aim_feeler,
// first_feeler_query) on the same hit, so the query asked here is the one shading would make,
// and the packet walk's answer is the single ray's: the picture does not change
// (tests/render/eye_feelers_test.cpp renders with and without the answers).
#include <algorithm>
#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "rt/render/ray_tracer.h"
#include "rt/shading/surface_point.h"

namespace rt {

namespace {

// Eye hits a run of rays needs before its feelers are planned ahead.
constexpr std::size_t kFewestHits = 8;

// An eye ray's hit is shaded with the full model: highlights, and -T's far-side feelers.
constexpr bool kHighlights = true;

// Plans the feeler from `s` toward `light` as shading would, into `answer` (Dark where none goes
// or none can bring light), and returns its first query, if it has one to ask.
std::optional<FeelerQuery> plan_feeler(const FeelerContext& context, const SurfacePoint& s,
                                       const PointLight& light, FeelerAnswer& answer) {
    answer.state = FeelerAnswer::State::Dark;
    answer.side = light_side(context.settings, s, light, kHighlights);
    if (!answer.side.feels || !aim_feeler(context, s.position, light, answer.aim)) {
        return std::nullopt;
    }
    std::optional<FeelerQuery> query = first_feeler_query(
        context, s.position, answer.aim.target - s.position, answer.aim.target_distance);
    if (query) {
        answer.along = query->along;
    }
    return query;
}

// Feelers gathered eight at a time, whichever rays they come from (most eye rays of a sparse
// scene hit nothing), each answer written to its FeelerAnswer. A lone feeler goes as a single
// ray: a packet of one costs more.
class FeelerPackets {
public:
    FeelerPackets(const Accelerator& accel, EyeFeelerRoom& room, TraceCounters& counters)
        : accel_(accel), packet_(room.packet), found_(room.found), counters_(counters) {}
    void add(const FeelerQuery& query, FeelerAnswer& answer) {
        packet_.rays[lanes_] = query.ray;
        packet_.t[lanes_] = query.along;
        answers_[lanes_] = &answer;
        if (++lanes_ == kPacketSize) {
            flush();
        }
    }
    void flush() {
        if (lanes_ == 1) {
            found_[0] = accel_.closest_hit(packet_.rays[0], packet_.t[0], counters_);
        } else if (lanes_ > 1) {
            packet_.active = (1u << lanes_) - 1u;
            accel_.closest_hit_packet(packet_, found_, counters_);
        }
        for (std::size_t lane = 0; lane < lanes_; ++lane) {
            FeelerAnswer& answer = *answers_[lane];
            answer.state = found_[lane] ? FeelerAnswer::State::Hits : FeelerAnswer::State::Misses;
            if (found_[lane]) {
                answer.hit = *found_[lane];
            }
        }
        lanes_ = 0;
    }

private:
    const Accelerator& accel_;
    RayPacket& packet_;
    PacketHits& found_;
    TraceCounters& counters_;
    std::array<FeelerAnswer*, kPacketSize> answers_{};
    std::size_t lanes_ = 0;
};

}  // namespace

void RayTracer::eye_feelers(std::span<const Ray> rays, std::span<const std::optional<Hit>> hits,
                            std::span<FeelerAnswer> answers, TraceCounters& counters,
                            EyeFeelerRoom& room) const {
    for (FeelerAnswer& answer : answers) {
        answer.state = FeelerAnswer::State::NotFound;
    }
    const std::size_t per_ray = eye_feelers_per_ray();
    if (per_ray == 0 || answers.size() != rays.size() * per_ray ||
        (stop_ != nullptr && stop_->load(std::memory_order_relaxed))) {
        return;
    }
    // Too few hits to fill a packet: planning the feelers ahead would cost more than their
    // packets save, and shading asks them one by one as usual.
    const auto hit_count = static_cast<std::size_t>(
        std::count_if(hits.begin(), hits.end(), [](const std::optional<Hit>& h) { return h; }));
    if (hit_count < kFewestHits) {
        return;
    }
    room.points.clear();
    room.ray_of.clear();
    for (std::size_t i = 0; i < rays.size(); ++i) {
        if (hits[i]) {
            room.points.push_back(describe_hit(scene_, settings_, rays[i], *hits[i]));
            room.ray_of.push_back(i);
        }
    }
    FeelerPackets packets(accel_, room, counters);
    for (std::size_t light = 0; light < per_ray; ++light) {
        for (std::size_t p = 0; p < room.points.size(); ++p) {
            const SurfacePoint& s = room.points[p];
            const FeelerContext context{scene_, accel_, settings_, epsilon_, nullptr, s.polygon};
            FeelerAnswer& answer = answers[room.ray_of[p] * per_ray + light];
            if (const std::optional<FeelerQuery> query =
                    plan_feeler(context, s, lights_[light], answer)) {
                packets.add(*query, answer);
            }
        }
        packets.flush();  // the next light's feelers go another way
    }
}

}  // namespace rt
