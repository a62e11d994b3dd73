#include "rt/app/memory_estimate.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "rt/accel/make_accelerator.h"
#include "rt/core/available_memory.h"
#include "rt/core/error.h"
#include "rt/window/picture_window.h"

#include <fmt/format.h>

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
        parts.push_back(
            {"the window", pixels(scene.view.width, scene.view.height) * kWindowBytesPerViewPixel});
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

}  // namespace rt
