#include "rt/app/memory_estimate.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "rt/accel/make_accelerator.h"
#include "rt/core/error.h"

#include <fmt/format.h>

#include <sys/resource.h>

namespace rt {

namespace {

constexpr std::uint64_t kFloatRgb = 3 * sizeof(float);
constexpr std::uint64_t kByteRgb = 3;
/// The octree's and the BVH's nodes and polygon references, a polygon's share: a few references
/// each (a polygon spans several voxels) and a node's worth; bench/voxel's scenes stay below it.
constexpr std::uint64_t kAccelBytesPerPolygon = 256;
/// A SEADS voxel: its offset into the polygon lists and its clearance byte (seads_grid.h).
constexpr std::uint64_t kSeadsBytesPerVoxel = sizeof(std::uint32_t) + 1;
/// The z-buffer's item buffer: a polygon id and a depth per view pixel.
constexpr std::uint64_t kZBufferBytesPerPixel = 2 * sizeof(float);

std::uint64_t pixels(int width, int height) {
    return static_cast<std::uint64_t>(std::max(width, 0)) *
           static_cast<std::uint64_t>(std::max(height, 0));
}

std::string lower_extension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

// Outputs are written one after another, so only the largest writer's buffers count.
MemoryPart largest_writer(const Options& options, const PixelRect& window) {
    std::vector<std::filesystem::path> paths(options.outputs.begin(), options.outputs.end());
    if (!options.no_gro) {
        paths.emplace_back("picture.gro");
    }
    const std::uint64_t n = pixels(window.width(), window.height());
    MemoryPart largest{"writing the outputs", 0};
    for (const std::filesystem::path& path : paths) {
        const std::string ext = lower_extension(path);
        MemoryPart part;
        if (ext == ".png") {
            part = {"the PNG", 2 * n * kByteRgb};  // the 8-bit picture and its encoding
        } else if (ext == ".ppm") {
            part = {"the PPM", n * kByteRgb};
        } else {
            // .gro and .exr stream from the film a row (or a block of rows) at a time.
            part = {"writing " + ext, static_cast<std::uint64_t>(window.width()) * kFloatRgb * 64};
        }
        if (part.bytes > largest.bytes) {
            largest = part;
        }
    }
    return largest;
}

MemoryPart intersection_method(const Scene& scene, const Options& options) {
    MemoryPart part{"the intersection method", scene.polygons.size() * kAccelBytesPerPolygon};
    const AccelSettings method = method_for_scene(scene, options.accel.method);
    if (method.kind == AccelKind::Seads && method.seads_resolution) {
        const auto side = static_cast<std::uint64_t>(std::max(*method.seads_resolution, 0));
        part.bytes += side * side * side * kSeadsBytesPerVoxel;
    }
    return part;
}

// The number after `key` in a "Key: value kB" file such as /proc/meminfo, in bytes.
std::optional<std::uint64_t> kib_field(const std::string& file, const std::string& key) {
    std::ifstream in(file);
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind(key, 0) == 0) {
            std::istringstream fields(line.substr(key.size()));
            std::uint64_t kib = 0;
            if (fields >> kib) {
                return kib * 1024;
            }
        }
    }
    return std::nullopt;
}

// A cgroup v2 file holding one number ("max" when unlimited).
std::optional<std::uint64_t> number_in(const std::string& file) {
    std::ifstream in(file);
    std::uint64_t value = 0;
    if (in >> value) {
        return value;
    }
    return std::nullopt;
}

void take_lower(std::optional<MemoryLimit>& limit, std::uint64_t bytes, const std::string& source) {
    if (!limit || bytes < limit->bytes) {
        limit = MemoryLimit{bytes, source};
    }
}

}  // namespace

MemoryPart texture_picture_part(const std::string& name, int width, int height) {
    return {fmt::format("the {} x {} texture picture '{}'", width, height, name),
            pixels(width, height) * kByteRgb, true};
}

std::vector<MemoryPart> estimate_render_memory(const Scene& scene, const Options& options,
                                               const PixelRect& window, bool window_opens) {
    std::vector<MemoryPart> parts;
    if (!options.random_rays) {  // -r keeps no picture
        parts.push_back({"the film", pixels(window.width(), window.height()) * kFloatRgb});
        parts.push_back(largest_writer(options, window));
    }
    if (window_opens) {
        // The window keeps the whole view's linear picture, and the wireframe drawn into it
        // is a whole view's film too; the 4-byte texture has a copy in the renderer. 32 bytes
        // a pixel, as measured: rt's peak memory grows 31 bytes a pixel from a 2048 x 2048 to
        // a 4096 x 4096 view, with the window open on Xvfb.
        parts.push_back({"the window", pixels(scene.view.width, scene.view.height) *
                                           (2 * kFloatRgb + 2 * sizeof(std::uint32_t))});
    }
    if (options.accel.zbuffer_first_hits) {
        parts.push_back(
            {"the z-buffer", pixels(scene.view.width, scene.view.height) * kZBufferBytesPerPixel});
    }
    parts.push_back(intersection_method(scene, options));
    for (const TextureImage& picture : scene.texture_images) {
        parts.push_back(texture_picture_part(picture.name, picture.width, picture.height));
    }
    return parts;
}

std::optional<MemoryLimit> available_memory() {
    std::optional<MemoryLimit> limit;
    if (const auto available = kib_field("/proc/meminfo", "MemAvailable:")) {
        take_lower(limit, *available, "MemAvailable in /proc/meminfo");
    }
    const auto cgroup_max = number_in("/sys/fs/cgroup/memory.max");
    const auto cgroup_used = number_in("/sys/fs/cgroup/memory.current");
    if (cgroup_max && cgroup_used) {
        take_lower(limit, *cgroup_max > *cgroup_used ? *cgroup_max - *cgroup_used : 0,
                   "the cgroup's memory.max");
    }
    rlimit address_space{};
    if (::getrlimit(RLIMIT_AS, &address_space) == 0 && address_space.rlim_cur != RLIM_INFINITY) {
        const std::uint64_t used = kib_field("/proc/self/status", "VmSize:").value_or(0);
        const std::uint64_t cap = address_space.rlim_cur;
        take_lower(limit, cap > used ? cap - used : 0, "the address-space limit (ulimit -v)");
    }
    return limit;
}

void check_memory(const std::vector<MemoryPart>& parts, const MemoryLimit& limit) {
    std::uint64_t total = 0;
    std::string listed;
    bool pictures = false;
    bool others = false;
    for (const MemoryPart& part : parts) {
        total += part.bytes;
        if (part.bytes >= (std::uint64_t{1} << 20)) {  // the parts that matter
            listed += (listed.empty() ? "" : ", ") + part.what + " " + format_bytes(part.bytes);
            (part.picture ? pictures : others) = true;
        }
    }
    if (total <= limit.bytes) {
        return;
    }
    // The ways out of the parts that are large; with none (a limit set very low), all of them.
    std::string ways;
    if (others || !pictures) {
        ways =
            "render a smaller output matrix or view area (the .scn's view lines), draw only "
            "from a line up (-L), ";
    }
    if (pictures) {
        ways += "use smaller texture pictures, ";
    }
    const bool with_window = std::any_of(parts.begin(), parts.end(), [](const MemoryPart& p) {
        return p.what == "the window" && p.bytes > 0;
    });
    if (with_window) {
        ways += "render without the window (--no-window), ";
    }
    // With no part of a MiB or more (a limit set very low) there is nothing worth listing.
    throw UsageError(fmt::format(
        "the render needs about {}{}, more than the {} available ({}): {}or set the limit with "
        "--max-memory GIB",
        format_bytes(total), listed.empty() ? "" : " (" + listed + ")", format_bytes(limit.bytes),
        limit.source, ways));
}

std::string format_bytes(std::uint64_t bytes) {
    const double kib = static_cast<double>(bytes) / 1024.0;
    if (kib >= 1024.0 * 1024.0) {
        return fmt::format("{:.1f} GiB", kib / (1024.0 * 1024.0));
    }
    if (kib >= 1024.0) {
        return fmt::format("{:.0f} MiB", kib / 1024.0);
    }
    if (bytes >= 1024) {
        return fmt::format("{:.0f} KiB", kib);
    }
    return fmt::format("{} byte{}", bytes, bytes == 1 ? "" : "s");
}

}  // namespace rt
