// What a render will hold in memory, estimated before anything big is allocated, and the check
// against the memory there is (docs/rendering.md, "Memory").
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "rt/app/options.h"
#include "rt/core/available_memory.h"
#include "rt/core/bounds.h"
#include "rt/scene/scene.h"

namespace rt {

struct MemoryPart {
    std::string what;  ///< "the film", "the PNG"
    std::uint64_t bytes = 0;
    bool picture = false;  ///< a texture picture: smaller pictures are the way out
};

/// A texture picture decoded (three bytes a pixel): "the 16384 x 16384 texture picture 'a.png'".
MemoryPart texture_picture_part(const std::string& name, int width, int height);

/// The big allocations of a render of `window` of the scene: the film (3 floats a pixel), the
/// window's picture (3 floats a view pixel) when one opens, each output's writing buffers, the
/// z-buffer, the intersection method from the polygon count (SEADS from its voxels too), and the
/// scene's texture pictures (counted when each is read, before it is decoded, and here with the
/// rest). The rest of the scene is in memory already and is not counted.
std::vector<MemoryPart> estimate_render_memory(const Scene& scene, const Options& options,
                                               const PixelRect& window, bool window_opens);

/// Throws UsageError when the parts add up to more than the limit, naming the figures and the
/// ways to proceed.
void check_memory(const std::vector<MemoryPart>& parts, const MemoryLimit& limit);

}  // namespace rt
