#include "rt/accel/embree/embree_accelerator.h"

#include <atomic>
#include <cfloat>
#include <cmath>
#include <string>
#include <vector>

#include "rt/core/error.h"

#include <embree3/rtcore.h>

namespace rt {

namespace {

float to_float_limit(double t) {
    return static_cast<float>(std::fmin(std::fmax(t, -FLT_MAX), FLT_MAX));
}

// Embree asserts (debug builds) or misbehaves on a ray it calls invalid: an origin or direction
// component beyond FLT_LARGE (1.844e18) or not a number. No scene the reader accepts makes one
// (docs/formats.md, the coordinate range); for other callers such a ray misses.
bool embree_accepts(const RTCRay& r) {
    constexpr float kLarge = 1.844e18f;  // Embree's FLT_LARGE
    for (const float v : {r.org_x, r.org_y, r.org_z, r.dir_x, r.dir_y, r.dir_z}) {
        if (!(std::fabs(v) <= kLarge)) {
            return false;
        }
    }
    return r.tnear <= r.tfar;  // also false when either is not a number
}

class EmbreeAccelerator : public Accelerator {
public:
    EmbreeAccelerator(const Scene& scene, unsigned build_threads);
    ~EmbreeAccelerator() override;
    EmbreeAccelerator(const EmbreeAccelerator&) = delete;
    EmbreeAccelerator& operator=(const EmbreeAccelerator&) = delete;

    std::string_view name() const override { return "embree"; }
    std::optional<Hit> closest_hit(const Ray& ray, Interval t,
                                   TraceCounters& counters) const override;
    bool occluded(const Ray& ray, Interval t, TraceCounters& counters) const override;
    /// Embree's own packet call, rtcIntersect8, so that the lab compares packets with packets.
    void closest_hit_packet(const RayPacket& packet, PacketHits& hits,
                            TraceCounters& counters) const override;
    std::size_t memory_bytes() const override {
        return static_cast<std::size_t>(std::max<long long>(0, allocated_.load())) +
               triangle_polygon_.capacity() * sizeof(std::uint32_t);
    }

private:
    // Embree reports its allocations here, so memory_bytes() is what it really holds.
    static bool track_memory(void* self, ssize_t bytes, bool /*post*/) {
        static_cast<EmbreeAccelerator*>(self)->allocated_ += bytes;
        return true;
    }
    void add_triangles(const Scene& scene);
    void throw_if_failed(const char* what) const;

    RTCDevice device_ = nullptr;
    RTCScene scene_ = nullptr;
    std::vector<std::uint32_t> triangle_polygon_;  ///< Embree's primID -> our polygon id
    std::atomic<long long> allocated_{0};
};

EmbreeAccelerator::EmbreeAccelerator(const Scene& scene, unsigned build_threads) {
    // Embree's device configuration: "threads=N" caps the threads of its builds.
    const std::string config = build_threads > 0 ? "threads=" + std::to_string(build_threads) : "";
    device_ = rtcNewDevice(config.c_str());
    if (device_ == nullptr) {
        throw Error("embree: cannot create a device");
    }
    rtcSetDeviceMemoryMonitorFunction(device_, &EmbreeAccelerator::track_memory, this);
    scene_ = rtcNewScene(device_);
    add_triangles(scene);
    rtcCommitScene(scene_);
    throw_if_failed("building the scene");
}

EmbreeAccelerator::~EmbreeAccelerator() {
    if (scene_ != nullptr) {
        rtcReleaseScene(scene_);
    }
    rtcReleaseDevice(device_);
}

void EmbreeAccelerator::throw_if_failed(const char* what) const {
    const RTCError error = rtcGetDeviceError(device_);
    if (error != RTC_ERROR_NONE) {
        throw Error(std::string("embree: error ") + std::to_string(static_cast<int>(error)) + " " +
                    what);
    }
}

// One triangle geometry: the scene's positions as floats, each polygon as a fan from corner 0.
void EmbreeAccelerator::add_triangles(const Scene& scene) {
    std::vector<std::uint32_t> indices;
    for (std::uint32_t id = 0; id < scene.polygons.size(); ++id) {
        const Polygon& p = scene.polygons[id];
        for (std::uint32_t i = 1; i + 1 < p.corner_count; ++i) {
            const std::uint32_t* c = scene.corners.data() + p.first_corner;
            indices.insert(indices.end(), {c[0], c[i], c[i + 1]});
            triangle_polygon_.push_back(id);
        }
    }
    if (triangle_polygon_.empty()) {
        return;  // an empty scene: every ray misses
    }
    RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                3 * sizeof(float), scene.positions.size()));
    for (std::size_t i = 0; i < scene.positions.size(); ++i) {
        for (int k = 0; k < 3; ++k) {
            vertices[3 * i + k] = static_cast<float>(scene.positions[i][k]);
        }
    }
    auto* triangles = static_cast<std::uint32_t*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                3 * sizeof(std::uint32_t), triangle_polygon_.size()));
    std::copy(indices.begin(), indices.end(), triangles);
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene_, geometry);
    rtcReleaseGeometry(geometry);
    throw_if_failed("adding the triangles");
}

RTCRay embree_ray(const Ray& ray, Interval t) {
    RTCRay r{};
    r.org_x = static_cast<float>(ray.origin.x);
    r.org_y = static_cast<float>(ray.origin.y);
    r.org_z = static_cast<float>(ray.origin.z);
    r.dir_x = static_cast<float>(ray.direction.x);
    r.dir_y = static_cast<float>(ray.direction.y);
    r.dir_z = static_cast<float>(ray.direction.z);
    r.tnear = to_float_limit(std::fmax(t.min, 0.0));
    r.tfar = to_float_limit(t.max);
    r.mask = ~0u;
    return r;
}

std::optional<Hit> EmbreeAccelerator::closest_hit(const Ray& ray, Interval t,
                                                  TraceCounters& /*counters*/) const {
    RTCIntersectContext context{};  // zeroed, then set by rtcInitIntersectContext
    rtcInitIntersectContext(&context);
    RTCRayHit hit{};
    hit.ray = embree_ray(ray, t);
    hit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    hit.hit.primID = RTC_INVALID_GEOMETRY_ID;
    if (!embree_accepts(hit.ray)) {
        return std::nullopt;
    }
    rtcIntersect1(scene_, &context, &hit);
    if (hit.hit.geomID == RTC_INVALID_GEOMETRY_ID) {
        return std::nullopt;
    }
    return Hit{static_cast<double>(hit.ray.tfar), triangle_polygon_[hit.hit.primID]};
}

void EmbreeAccelerator::closest_hit_packet(const RayPacket& packet, PacketHits& hits,
                                           TraceCounters& /*counters*/) const {
    RTCIntersectContext context{};  // zeroed, then set by rtcInitIntersectContext
    rtcInitIntersectContext(&context);
    alignas(32) int valid[kPacketSize] = {};
    alignas(32) RTCRayHit8 rays{};
    for (int lane = 0; lane < kPacketSize; ++lane) {
        if (((packet.active >> lane) & 1u) == 0) {
            continue;
        }
        const RTCRay r = embree_ray(packet.rays[lane], packet.t[lane]);
        hits[lane] = std::nullopt;
        if (!embree_accepts(r)) {
            continue;
        }
        valid[lane] = -1;
        rays.ray.org_x[lane] = r.org_x;
        rays.ray.org_y[lane] = r.org_y;
        rays.ray.org_z[lane] = r.org_z;
        rays.ray.dir_x[lane] = r.dir_x;
        rays.ray.dir_y[lane] = r.dir_y;
        rays.ray.dir_z[lane] = r.dir_z;
        rays.ray.tnear[lane] = r.tnear;
        rays.ray.tfar[lane] = r.tfar;
        rays.ray.mask[lane] = r.mask;
        rays.hit.geomID[lane] = RTC_INVALID_GEOMETRY_ID;
        rays.hit.primID[lane] = RTC_INVALID_GEOMETRY_ID;
    }
    rtcIntersect8(valid, scene_, &context, &rays);
    for (int lane = 0; lane < kPacketSize; ++lane) {
        if (valid[lane] != 0 && rays.hit.geomID[lane] != RTC_INVALID_GEOMETRY_ID) {
            hits[lane] = Hit{static_cast<double>(rays.ray.tfar[lane]),
                             triangle_polygon_[rays.hit.primID[lane]]};
        }
    }
}

bool EmbreeAccelerator::occluded(const Ray& ray, Interval t, TraceCounters& /*counters*/) const {
    RTCIntersectContext context{};  // zeroed, then set by rtcInitIntersectContext
    rtcInitIntersectContext(&context);
    RTCRay r = embree_ray(ray, t);
    if (!embree_accepts(r)) {
        return false;
    }
    rtcOccluded1(scene_, &context, &r);
    return r.tfar < 0.0f && std::isinf(r.tfar);
}

}  // namespace

std::unique_ptr<Accelerator> make_embree_accelerator(const Scene& scene, unsigned build_threads) {
    return std::make_unique<EmbreeAccelerator>(scene, build_threads);
}

}  // namespace rt
