// The shadow feelers from eye hits, eight at a time (issue 15): rays of neighbouring samples hit
// neighbouring points, and their feelers toward one light point are coherent, as the eye rays
// were. Each feeler is planned by the steps shading takes (light_side, aim_feeler,
// first_feeler_query) on the same hit, so the query asked here is the one shading would make,
// and the packet walk's answer is the single ray's: the picture does not change
// (tests/render/eye_feelers_test.cpp renders with and without the answers).
#include <algorithm>
#include <cstddef>
#include <optional>
#include <vector>

#include "rt/render/ray_tracer.h"
#include "rt/shading/surface_point.h"

namespace rt {

namespace {

// Eye hits a run of rays needs before its feelers are planned ahead.
constexpr std::size_t kFewestHits = 8;

}  // namespace

void RayTracer::eye_feelers(std::span<const Ray> rays, std::span<const std::optional<Hit>> hits,
                            std::span<FeelerAnswer> answers, TraceCounters& counters,
                            EyeFeelerRoom& room) const {
    for (FeelerAnswer& answer : answers) {
        answer.state = FeelerAnswer::State::NotFound;
    }
    const std::size_t per_ray = eye_feelers_per_ray();
    if (per_ray == 0 || (stop_ != nullptr && stop_->load(std::memory_order_relaxed))) {
        return;
    }
    // Too few hits to fill a packet: planning the feelers ahead would cost more than their
    // packets save, and shading asks them one by one as usual.
    const auto hit_count = static_cast<std::size_t>(
        std::count_if(hits.begin(), hits.end(), [](const std::optional<Hit>& h) { return h; }));
    if (hit_count < kFewestHits) {
        return;
    }
    std::vector<SurfacePoint>& points = room.points;
    std::vector<std::size_t>& ray_of = room.ray_of;
    points.clear();
    ray_of.clear();
    for (std::size_t i = 0; i < rays.size(); ++i) {
        if (hits[i]) {
            points.push_back(describe_hit(scene_, settings_, rays[i], *hits[i]));
            ray_of.push_back(i);
        }
    }
    // An eye ray's hit is shaded with the full model: highlights, and -T's far-side feelers.
    constexpr bool kHighlights = true;
    RayPacket& packet = room.packet;
    PacketHits& found = room.found;
    std::array<std::size_t, kPacketSize> answer_of{};  // each lane's place in `answers`
    int lanes = 0;
    // The feelers toward one light go eight at a time, whichever rays they come from: most eye
    // rays of a sparse scene hit nothing, and a packet of one or two lanes costs more than the
    // single rays.
    const auto flush = [&] {
        if (lanes == 1) {
            found[0] = accel_.closest_hit(packet.rays[0], packet.t[0], counters);
        } else if (lanes > 1) {
            packet.active = (1u << static_cast<unsigned>(lanes)) - 1u;
            accel_.closest_hit_packet(packet, found, counters);
        }
        for (int lane = 0; lane < lanes; ++lane) {
            FeelerAnswer& answer = answers[answer_of[static_cast<std::size_t>(lane)]];
            answer.state = found[lane] ? FeelerAnswer::State::Hits : FeelerAnswer::State::Misses;
            if (found[lane]) {
                answer.hit = *found[lane];
            }
        }
        lanes = 0;
    };
    for (std::size_t light = 0; light < per_ray; ++light) {
        const PointLight& point_light = lights_[light];
        for (std::size_t p = 0; p < points.size(); ++p) {
            const SurfacePoint& s = points[p];
            const std::size_t i = ray_of[p];
            FeelerAnswer& answer = answers[i * per_ray + light];
            answer.state = FeelerAnswer::State::Dark;
            answer.side = light_side(settings_, s, point_light, kHighlights);
            if (!answer.side.feels) {
                continue;
            }
            const FeelerContext context{scene_, accel_, settings_, epsilon_, nullptr, s.polygon};
            if (!aim_feeler(context, s.position, point_light, answer.aim)) {
                continue;
            }
            const std::optional<FeelerQuery> query = first_feeler_query(
                context, s.position, answer.aim.target - s.position, answer.aim.target_distance);
            if (!query) {
                continue;
            }
            answer.along = query->along;
            packet.rays[lanes] = query->ray;
            packet.t[lanes] = query->along;
            answer_of[static_cast<std::size_t>(lanes)] = i * per_ray + light;
            if (++lanes == kPacketSize) {
                flush();
            }
        }
        flush();
    }
}

}  // namespace rt
