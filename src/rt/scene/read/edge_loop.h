// The corner loop of a filetype-0 polygon from its edges (manual 2.5 lists edges, not corners).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace rt {

struct Edge {
    std::uint32_t a = 0;  ///< vertex indices, in either orientation
    std::uint32_t b = 0;
};

/// The closed loop the edges form: in the listed order when consecutive edges share a vertex,
/// otherwise assembled from the edge set. Empty when they form no single closed loop.
std::vector<std::uint32_t> chain_edges(std::span<const Edge> edges);

}  // namespace rt
