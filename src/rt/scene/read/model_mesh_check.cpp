#include "rt/scene/read/model_mesh_check.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "rt/core/huge_pages.h"
#include "rt/core/prefetch.h"
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

// Slots for an open-addressing table of at most `keys` keys: a power of two with a quarter more
// room than that, so that it never fills (a model's distinct positions are far fewer than the
// bound). In fresh memory every page is faulted in and zeroed, so the table is no bigger than
// this, and on huge pages.
std::size_t table_size(std::size_t keys) {
    return std::bit_ceil(std::max<std::size_t>(16, keys + keys / 4 + 1));
}

std::uint64_t position_hash(const PositionKey& k) {
    const std::uint64_t h = k.x ^ (k.y * 0x9e3779b97f4a7c15ULL) ^ (k.z * 0xc2b2ae3d27d4eb4fULL);
    return (h ^ (h >> 29)) * 0xbf58476d1ce4e5b9ULL;
}

// The first vertex at each position, by open addressing over one array of slots, each a vertex
// index and, above it, the high half of its position's hash: no allocation per vertex (a
// std::unordered_map of the keys took a fifth of a million-triangle model's load, most of it in
// the kernel handing out memory for its nodes). The hash's half is compared before the position:
// a lookup passes several taken slots (the table is up to 4/5 full), and reading each one's
// vertex was a cache miss into the whole model.
class FirstVertexAt {
public:
    explicit FirstVertexAt(const std::vector<Vec3>& vertices)
        : vertices_(vertices), mask_(table_size(vertices.size()) - 1) {
        reserve_huge(slots_, mask_ + 1);
        slots_.resize(mask_ + 1, kEmpty);
    }

    /// Asks for the slot first_at(v) looks at first: a big model's positions land all over the
    /// table, and each lookup would otherwise wait for its own cache miss.
    void prefetch_slot(std::uint32_t v) const {
        prefetch(&slots_[position_hash(PositionKey(vertices_[v])) & mask_]);
    }

    /// The first vertex before `v` at v's position, or v itself (which is then recorded).
    std::uint32_t first_at(std::uint32_t v) {
        const PositionKey key(vertices_[v]);
        const std::uint64_t hash = position_hash(key);
        const std::uint64_t tag = hash & kTagBits;
        for (std::size_t i = hash & mask_;; i = (i + 1) & mask_) {
            const std::uint64_t slot = slots_[i];
            if (slot == kEmpty) {
                slots_[i] = tag | v;
                return v;
            }
            const auto first = static_cast<std::uint32_t>(slot);
            if ((slot & kTagBits) == tag && PositionKey(vertices_[first]) == key) {
                return first;
            }
        }
    }

private:
    static constexpr std::uint64_t kTagBits = 0xffffffff00000000ULL;
    // Never a slot: vertex 0xffffffff does not exist (a file holds fewer vertices).
    static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
    const std::vector<Vec3>& vertices_;
    std::size_t mask_;
    std::vector<std::uint64_t> slots_;
};

// How many undirected edges border one polygon only (`open`) and more than two (`crowded`). Each
// edge is listed under its lower corner (counted, then placed, as in a counting sort), and each
// corner's short list is sorted: equal entries are one edge's uses. An open-addressing table of
// the edges took a cache miss per insertion, into 36 MB for a million triangles (the soup's load
// took 1.46 s with it, 1.22 s without); the lists take 4 bytes an edge, written and read in the
// order of the corners.
void count_edge_uses(const SurfaceMesh& mesh, std::size_t& open, std::size_t& crowded) {
    std::size_t corners_seen = 0;
    for (const std::uint32_t c : mesh.corners) {
        corners_seen = std::max(corners_seen, std::size_t{c} + 1);
    }
    std::vector<std::size_t> start(corners_seen + 1, 0);
    const auto for_each_edge = [&](auto&& f) {
        for (const MeshPolygon& p : mesh.polygons) {
            for (std::uint32_t k = 0; k < p.corner_count; ++k) {
                const std::uint32_t a = mesh.corners[p.first_corner + k];
                const std::uint32_t b = mesh.corners[p.first_corner + (k + 1) % p.corner_count];
                f(std::min(a, b), std::max(a, b));
            }
        }
    };
    for_each_edge([&](std::uint32_t low, std::uint32_t) { ++start[low + 1]; });
    for (std::size_t v = 1; v < start.size(); ++v) {
        start[v] += start[v - 1];
    }
    std::vector<std::uint32_t> other(start.back());
    std::vector<std::size_t> filled(start.begin(), start.end() - 1);
    for_each_edge([&](std::uint32_t low, std::uint32_t high) { other[filled[low]++] = high; });
    open = 0;
    crowded = 0;
    for (std::size_t v = 0; v + 1 < start.size(); ++v) {
        const auto first = other.begin() + static_cast<std::ptrdiff_t>(start[v]);
        const auto last = other.begin() + static_cast<std::ptrdiff_t>(start[v + 1]);
        std::sort(first, last);
        for (auto run = first; run != last;) {
            const auto next = std::find_if(run, last, [&](std::uint32_t b) { return b != *run; });
            const auto uses = next - run;
            open += uses == 1 ? 1 : 0;
            crowded += uses > 2 ? 1 : 0;
            run = next;
        }
    }
}

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

// Out of line: inlined into weld_vertices, GCC 12 mistook the copy's release for freeing a
// pointer into the middle of a block (-Wfree-nonheap-object).
[[gnu::noinline]] bool sorted_has_repeat(std::vector<std::uint32_t> loop) {
    std::sort(loop.begin(), loop.end());
    return std::adjacent_find(loop.begin(), loop.end()) != loop.end();
}

bool visits_a_corner_twice(const std::vector<std::uint32_t>& loop) {
    if (loop.size() <= 16) {  // most polygons: no copy, no allocation
        for (std::size_t i = 0; i < loop.size(); ++i) {
            if (std::find(loop.begin() + static_cast<std::ptrdiff_t>(i) + 1, loop.end(), loop[i]) !=
                loop.end()) {
                return true;
            }
        }
        return false;
    }
    return sorted_has_repeat(loop);
}

// Vertices whose slot is asked for ahead of their lookup (FirstVertexAt::prefetch_slot).
constexpr std::uint32_t kLookAhead = 16;

}  // namespace

// In place: a million-triangle model's welded copy (its polygon records alone 80 MB) was fresh
// memory, page by page, and the old arrays lived on beside it until the end.
void weld_vertices(SurfaceMesh& mesh, const std::string& name, Diagnostics& diagnostics) {
    // Each vertex's place among the first vertices at each position, in order. Found before any
    // vertex moves: the table compares positions through the vertices' old places.
    std::vector<std::uint32_t> welded;
    reserve_whole_huge_pages(welded, mesh.vertices.size());
    welded.resize(mesh.vertices.size());
    std::uint32_t kept = 0;
    {
        FirstVertexAt first(mesh.vertices);
        const auto count = static_cast<std::uint32_t>(mesh.vertices.size());
        for (std::uint32_t v = 0; v < count; ++v) {
            if (count - v > kLookAhead) {
                first.prefetch_slot(v + kLookAhead);
            }
            const std::uint32_t f = first.first_at(v);
            welded[v] = f == v ? kept++ : welded[f];
        }
    }
    // A first vertex's place is the number of first vertices before it: never above its own.
    for (std::uint32_t v = 0, next = 0; v < mesh.vertices.size(); ++v) {
        if (welded[v] == next) {
            mesh.vertices[next++] = mesh.vertices[v];
        }
    }
    mesh.vertices.resize(kept);
    std::vector<int>().swap(mesh.vertex_lines);  // they no longer match the vertices
    // Each polygon's loop is read before it is written back, no higher than it was: the loops lie
    // one after the other in polygon order (SurfaceMesh::add_polygon), and dropping corners only
    // moves them down.
    const bool has_normals = !mesh.corner_normals.empty();
    std::vector<std::uint32_t> loop;
    std::vector<Vec3> normals;
    std::size_t corners = 0;
    std::size_t polygons = 0;
    for (std::size_t i = 0; i < mesh.polygons.size(); ++i) {
        MeshPolygon p = mesh.polygons[i];
        if (p.first_corner < corners) {
            throw std::logic_error("weld_vertices: polygon loops out of order");
        }
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
            diagnostics.warn_repeated(
                fmt::format("polygons through one corner twice in {}", name),
                fmt::format("{}: polygon {} passes through one corner twice; skipped", name,
                            p.number));
            continue;
        }
        p.first_corner = static_cast<std::uint32_t>(corners);
        p.corner_count = static_cast<std::uint32_t>(loop.size());
        std::copy(loop.begin(), loop.end(),
                  mesh.corners.begin() + static_cast<std::ptrdiff_t>(corners));
        if (has_normals) {
            std::copy(normals.begin(), normals.end(),
                      mesh.corner_normals.begin() + static_cast<std::ptrdiff_t>(corners));
        }
        corners += loop.size();
        mesh.polygons[polygons++] = p;
    }
    mesh.polygons.resize(polygons);
    mesh.corners.resize(corners);
    if (has_normals) {
        mesh.corner_normals.resize(corners);
    }
}

void warn_if_not_watertight(const SurfaceMesh& mesh, const std::string& name,
                            Diagnostics& diagnostics) {
    std::size_t open = 0;
    std::size_t crowded = 0;
    count_edge_uses(mesh, open, crowded);
    if (open == 0 && crowded == 0) {
        return;
    }
    std::string why;
    if (open > 0) {
        why =
            fmt::format("{} {} one polygon only", count_of(static_cast<std::int64_t>(open), "edge"),
                        open == 1 ? "borders" : "border");
    }
    if (crowded > 0) {
        why += fmt::format("{}{} {} more than two", why.empty() ? "" : ", ",
                           count_of(static_cast<std::int64_t>(crowded), "edge"),
                           crowded == 1 ? "borders" : "border");
    }
    diagnostics.warn(name + ": the model is not watertight: " + why);
}

}  // namespace rt
