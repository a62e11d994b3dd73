#include "rt/cluster/helper.h"

#include <chrono>
#include <cstdint>
#include <thread>

#include "rt/app/input_digest.h"
#include "rt/app/interrupt.h"
#include "rt/cluster/cluster_error.h"
#include "rt/cluster/local_render.h"
#include "rt/cluster/protocol.h"
#include "rt/render/ray_kinds.h"

#include <fmt/format.h>

namespace rt::cluster {

Helper::Helper(MpiWorld& world, std::string identity)
    : world_(world), identity_(std::move(identity)) {}

void Helper::render(const Scene& scene, const Accelerator& accel, const RenderSettings& settings) {
    const PixelRect& w = settings.window;
    world_.send(
        0, kHello,
        Packer()
            .put_text(identity_ + fmt::format(" window {} {} {} {} inputs {}", w.left, w.top,
                                              w.right, w.bottom, input_digest(scene)))
            .bytes);
    LocalRender local(scene, accel, settings);
    bool asked = false;
    while (true) {
        if (interrupt_requested()) {
            throw ClusterError("stopped by a signal");
        }
        bool busy = false;
        if (!asked && !local.rows().closed() && local.rows().waiting() < local.threads()) {
            world_.send(0, kRequest, {});
            asked = true;
        }
        while (const std::optional<MpiWorld::Message> m = world_.poll()) {
            busy = true;
            Unpacker in(m->bytes);
            std::int32_t first = 0;
            std::int32_t count = 0;
            if (m->tag == kWork && in.get(first) && in.get(count)) {
                asked = false;
                for (int i = first; i < first + count; ++i) {
                    local.rows().push(w.bottom - i);
                }
                if (count == 0) {
                    local.rows().close();
                }
            } else if (m->tag == kStop) {
                local.stop();
            }
        }
        const bool done = local.done();  // before taking the rows: none is left behind
        for (const FinishedRow& row : local.take_finished()) {
            world_.send(0, kRow,
                        Packer()
                            .put(std::int32_t{row.y})
                            .put(row.samples)
                            .put_all(std::span<const float>(row.pixels))
                            .bytes);
            busy = true;
        }
        if (done) {
            break;
        }
        if (!busy) {
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
    }
    const RenderStatistics statistics = local.join();
    last_message(kDone,
                 Packer().put(statistics.unrepresentable_samples).put(statistics.by_kind).bytes);
}

void Helper::finish() {
    last_message(kDone, Packer().put(std::uint64_t{0}).put(KindCounters{}).bytes);
}

void Helper::fail(const std::string& message) {
    last_message(kFailed, Packer().put_text(message).bytes);
}

void Helper::last_message(int tag, const std::vector<std::byte>& bytes) {
    if (!finished_) {
        finished_ = true;
        world_.send(0, tag, bytes);
    }
}

}  // namespace rt::cluster
