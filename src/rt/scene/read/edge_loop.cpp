#include "rt/scene/read/edge_loop.h"

#include <algorithm>
#include <unordered_map>

namespace rt {

namespace {

bool touches(const Edge& e, std::uint32_t v) {
    return e.a == v || e.b == v;
}
std::uint32_t other_end(const Edge& e, std::uint32_t v) {
    return e.a == v ? e.b : e.a;
}

std::vector<std::uint32_t> chain_in_listed_order(std::span<const Edge> edges) {
    const Edge& first = edges[0];
    // Orient the first edge so that it ends where the second one starts.
    const bool forward = touches(edges[1], first.b);
    if (!forward && !touches(edges[1], first.a)) {
        return {};
    }
    const std::uint32_t start = forward ? first.a : first.b;
    std::uint32_t at = forward ? first.b : first.a;
    std::vector<std::uint32_t> loop{start};
    loop.reserve(edges.size());
    for (std::size_t i = 1; i < edges.size(); ++i) {
        if (!touches(edges[i], at)) {
            return {};
        }
        loop.push_back(at);
        at = other_end(edges[i], at);
    }
    if (at != start) {
        return {};
    }
    // A loop through some vertex twice (a figure of eight) is not one polygon.
    std::vector<std::uint32_t> sorted = loop;
    std::sort(sorted.begin(), sorted.end());
    const bool simple = std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end();
    return simple ? loop : std::vector<std::uint32_t>{};
}

// Every vertex of a single closed loop has exactly two of the edges; walk them from the first.
std::vector<std::uint32_t> chain_from_set(std::span<const Edge> edges) {
    std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> at_vertex;
    for (std::uint32_t i = 0; i < edges.size(); ++i) {
        if (edges[i].a == edges[i].b) {
            return {};
        }
        at_vertex[edges[i].a].push_back(i);
        at_vertex[edges[i].b].push_back(i);
    }
    for (const auto& [vertex, list] : at_vertex) {
        if (list.size() != 2) {
            return {};
        }
    }
    std::vector<std::uint32_t> loop{edges[0].a};
    std::uint32_t edge = 0;
    std::uint32_t at = edges[0].b;
    while (at != edges[0].a) {
        loop.push_back(at);
        const auto& pair = at_vertex[at];
        edge = pair[0] == edge ? pair[1] : pair[0];
        at = other_end(edges[edge], at);
        if (loop.size() > edges.size()) {
            return {};
        }
    }
    return loop.size() == edges.size() ? loop : std::vector<std::uint32_t>{};
}

}  // namespace

std::vector<std::uint32_t> chain_edges(std::span<const Edge> edges) {
    if (edges.size() < 3) {
        return {};
    }
    std::vector<std::uint32_t> loop = chain_in_listed_order(edges);
    return loop.empty() ? chain_from_set(edges) : loop;
}

}  // namespace rt
