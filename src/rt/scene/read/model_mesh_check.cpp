#include "rt/scene/read/model_mesh_check.h"

#include <algorithm>
#include <bit>
#include <unordered_map>

#include "rt/scene/read/field_reader.h"

#include <fmt/format.h>

namespace rt {

namespace {

// A position's exact bits, with -0 taken as 0 so that the two spellings of zero meet.
struct PositionKey {
    std::uint64_t x = 0;
    std::uint64_t y = 0;
    std::uint64_t z = 0;
    explicit PositionKey(const Vec3& p)
        : x(std::bit_cast<std::uint64_t>(p.x + 0.0)),
          y(std::bit_cast<std::uint64_t>(p.y + 0.0)),
          z(std::bit_cast<std::uint64_t>(p.z + 0.0)) {}
    bool operator==(const PositionKey&) const = default;
};

struct PositionHash {
    std::size_t operator()(const PositionKey& k) const {
        return std::hash<std::uint64_t>{}(k.x ^ (k.y * 0x9e3779b97f4a7c15ULL) ^
                                          (k.z * 0xc2b2ae3d27d4eb4fULL));
    }
};

// The loop with corners that repeat their predecessor (cyclically) dropped; normals follow.
void drop_repeats(std::vector<std::uint32_t>& loop, std::vector<Vec3>& normals) {
    std::size_t kept = 0;
    for (std::size_t k = 0; k < loop.size(); ++k) {
        if (kept > 0 && loop[k] == loop[kept - 1]) {
            continue;
        }
        loop[kept] = loop[k];
        if (!normals.empty()) {
            normals[kept] = normals[k];
        }
        ++kept;
    }
    while (kept > 1 && loop[kept - 1] == loop[0]) {
        --kept;
    }
    loop.resize(kept);
    normals.resize(normals.empty() ? 0 : kept);
}

bool visits_a_corner_twice(std::vector<std::uint32_t> loop) {
    std::sort(loop.begin(), loop.end());
    return std::adjacent_find(loop.begin(), loop.end()) != loop.end();
}

}  // namespace

void weld_vertices(SurfaceMesh& mesh, const std::string& name, Diagnostics& diagnostics) {
    std::unordered_map<PositionKey, std::uint32_t, PositionHash> index_of;
    index_of.reserve(mesh.vertices.size());
    std::vector<Vec3> vertices;
    std::vector<std::uint32_t> welded(mesh.vertices.size());
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
        const auto [it, fresh] = index_of.emplace(PositionKey(mesh.vertices[v]),
                                                  static_cast<std::uint32_t>(vertices.size()));
        if (fresh) {
            vertices.push_back(mesh.vertices[v]);
        }
        welded[v] = it->second;
    }
    SurfaceMesh out;
    out.vertices = std::move(vertices);
    out.materials = std::move(mesh.materials);
    const bool has_normals = !mesh.corner_normals.empty();
    std::vector<std::uint32_t> loop;
    std::vector<Vec3> normals;
    for (const MeshPolygon& p : mesh.polygons) {
        loop.clear();
        normals.clear();
        for (std::uint32_t k = 0; k < p.corner_count; ++k) {
            loop.push_back(welded[mesh.corners[p.first_corner + k]]);
            if (has_normals) {
                normals.push_back(mesh.corner_normals[p.first_corner + k]);
            }
        }
        drop_repeats(loop, normals);
        if (visits_a_corner_twice(loop)) {
            diagnostics.warn(fmt::format("{}: polygon {} passes through one corner twice; skipped",
                                         name, p.number));
            continue;
        }
        out.add_polygon(p, loop);
        out.corner_normals.insert(out.corner_normals.end(), normals.begin(), normals.end());
    }
    mesh = std::move(out);
}

void warn_if_not_watertight(const SurfaceMesh& mesh, const std::string& name,
                            Diagnostics& diagnostics) {
    std::unordered_map<std::uint64_t, std::uint32_t> uses;  // undirected edge -> polygons
    uses.reserve(mesh.corners.size());
    for (const MeshPolygon& p : mesh.polygons) {
        for (std::uint32_t k = 0; k < p.corner_count; ++k) {
            std::uint64_t a = mesh.corners[p.first_corner + k];
            std::uint64_t b = mesh.corners[p.first_corner + (k + 1) % p.corner_count];
            if (a > b) {
                std::swap(a, b);
            }
            ++uses[(a << 32) | b];
        }
    }
    std::size_t open = 0;
    std::size_t crowded = 0;
    for (const auto& [edge, count] : uses) {
        open += count == 1 ? 1 : 0;
        crowded += count > 2 ? 1 : 0;
    }
    if (open == 0 && crowded == 0) {
        return;
    }
    std::string why;
    if (open > 0) {
        why = fmt::format("{} border one polygon only",
                          count_of(static_cast<std::int64_t>(open), "edge"));
    }
    if (crowded > 0) {
        why += fmt::format("{}{} border more than two", why.empty() ? "" : ", ",
                           count_of(static_cast<std::int64_t>(crowded), "edge"));
    }
    diagnostics.warn(name + ": the model is not watertight: " + why);
}

}  // namespace rt
