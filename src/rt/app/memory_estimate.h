// What a render will hold in memory, estimated before anything big is allocated, and the check
// against the memory there is (docs/rendering.md, "Memory").
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "rt/app/options.h"
#include "rt/core/bounds.h"
#include "rt/scene/scene.h"

namespace rt {

struct MemoryPart {
    std::string what;  ///< "the film", "the PNG"
    std::uint64_t bytes = 0;
};

/// The big allocations of a render of `window` of the scene: the film (3 floats a pixel), the
/// window's picture (3 floats a view pixel) when one opens, each output's writing buffers, the
/// z-buffer, and the intersection method from the polygon count (SEADS from its voxels too).
/// The scene itself is in memory already and is not counted.
std::vector<MemoryPart> estimate_render_memory(const Scene& scene, const Options& options,
                                               const PixelRect& window, bool window_opens);

/// The memory this process may still take: the least of MemAvailable (/proc/meminfo), the cgroup's
/// memory.max less its memory.current, and RLIMIT_AS less the address space in use. Empty when
/// none can be read.
struct MemoryLimit {
    std::uint64_t bytes = 0;
    std::string source;  ///< "MemAvailable in /proc/meminfo", "--max-memory"
};
std::optional<MemoryLimit> available_memory();

/// Throws UsageError when the parts add up to more than the limit, naming the figures and the
/// ways to proceed.
void check_memory(const std::vector<MemoryPart>& parts, const MemoryLimit& limit);

/// "3.2 GiB", "512 MiB".
std::string format_bytes(std::uint64_t bytes);

}  // namespace rt
