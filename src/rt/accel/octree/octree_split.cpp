#include "rt/accel/octree/octree_split.h"

#include <algorithm>
#include <bit>
#include <cstddef>
#include <new>
#include <numeric>
#include <string>

#include "rt/accel/voxel/polygon_box_overlap.h"
#include "rt/core/error.h"
#include "rt/core/prefetch.h"

namespace rt {

namespace {

std::uint64_t pool_limit(int power) {
    return std::uint64_t{1} << power;
}

}  // namespace

OctreeCell OctreeCell::child(int c) const {
    OctreeCell out;
    out.size = size / 2;
    out.level = level + 1;
    for (int a = 0; a < 3; ++a) {
        out.origin[a] = origin[a] + (((c >> a) & 1) != 0 ? out.size : 0);
    }
    return out;
}

OctreeFill::OctreeFill(const Scene& scene, const OctreeBuildSettings& settings, bool no_fudge)
    : scene_(scene) {
    // The header's depth comes unchecked; a switch's is in range already.
    const int depth = settings.depth.value_or(-1);
    if (depth < 0 || depth > kMaxOctreeDepth) {
        throw SettingError("octree depth", "the octree depth " + std::to_string(depth) +
                                               ": expected 0 to " +
                                               std::to_string(kMaxOctreeDepth));
    }
    octlist_power_ = settings.octlist_power.value_or(kDefaultOctlistPower);
    if (octlist_power_ < 0 || octlist_power_ > 31) {
        throw SettingError("octree node limit", "the octree node limit 2^" +
                                                    std::to_string(octlist_power_) +
                                                    ": expected a power from 0 to 31");
    }
    max_nodes_ = pool_limit(octlist_power_);
    const int seed =
        std::clamp(settings.seed_size_power.value_or(kDefaultSeedSizePower), 0, octlist_power_);
    tree_.depth = depth;
    tree_.world = world_box(scene, true);
    tree_.step = tree_.world.extent() * (1.0 / static_cast<double>(std::int64_t{1} << tree_.depth));
    tree_.per_step = {1.0 / tree_.step.x, 1.0 / tree_.step.y, 1.0 / tree_.step.z};
    // -ss: the pool's first allocation; it then doubles as needed, up to the -ol limit.
    try {
        tree_.nodes.reserve(pool_limit(seed));
    } catch (const std::bad_alloc&) {
        throw SettingError("octree seed size", "cannot allocate 2^" + std::to_string(seed) +
                                                   " octree nodes at once: lower the octree "
                                                   "seed size");
    }
    tree_.nodes.emplace_back();
    fudge_ = voxel_fudge(tree_.world, no_fudge);
    bounds_.reserve(scene.polygons.size());
    for (std::uint32_t id = 0; id < scene.polygons.size(); ++id) {
        bounds_.push_back(polygon_bounds(scene, id));
    }
}

std::vector<std::uint32_t> OctreeFill::all_polygons() const {
    std::vector<std::uint32_t> ids(scene_.polygons.size());
    std::iota(ids.begin(), ids.end(), 0u);
    return ids;
}

void OctreeFill::check_node_count(std::size_t nodes) const {
    if (nodes > max_nodes_) {
        throw SettingError("octree node limit",
                           "the octree of depth " + std::to_string(tree_.depth) +
                               " needs more than 2^" + std::to_string(octlist_power_) + " = " +
                               std::to_string(max_nodes_) +
                               " nodes: raise the octree node limit, now 2^" +
                               std::to_string(octlist_power_) + ", or lower the octree depth");
    }
}

std::uint32_t OctreeFill::allocate_children(OctreeTree& tree) const {
    check_node_count(tree.nodes.size() + 8);
    const auto first = static_cast<std::uint32_t>(tree.nodes.size());
    try {
        tree.nodes.resize(tree.nodes.size() + 8);
    } catch (const std::bad_alloc&) {
        throw SettingError("octree node limit",
                           "the octree of depth " + std::to_string(tree_.depth) +
                               " ran out of memory at " + std::to_string(tree.nodes.size()) +
                               " nodes: lower the octree node limit, now 2^" +
                               std::to_string(octlist_power_) + ", or the octree depth");
    }
    return first;
}

void OctreeFill::make_leaf(OctreeTree& tree, std::uint32_t index,
                           const std::vector<std::uint32_t>& polygons) const {
    if (tree.polygons.size() + polygons.size() >= OctreeNode::kInterior) {
        throw SettingError("octree depth",
                           "the octree holds more than 2^32 polygon references: lower the "
                           "octree depth");
    }
    tree.nodes[index] = {static_cast<std::uint32_t>(tree.polygons.size()),
                         static_cast<std::uint32_t>(polygons.size())};
    tree.polygons.insert(tree.polygons.end(), polygons.begin(), polygons.end());
}

Box3 OctreeFill::cell_box(const OctreeCell& cell) const {
    Box3 box;
    for (int a = 0; a < 3; ++a) {
        box.lo[a] = tree_.lattice(a, cell.origin[a]);
        box.hi[a] = tree_.lattice(a, cell.origin[a] + cell.size);
    }
    return box;
}

int OctreeFill::children_reached(std::uint32_t polygon, const double middle[3]) const {
    // Which halves along each axis the polygon's box reaches (the node's own box it reaches
    // already). Child c takes the upper half on the axes of its set bits, the lower on the others.
    const Box3& b = bounds_[polygon];
    int lower = 0;
    int upper = 0;
    for (int a = 0; a < 3; ++a) {
        lower |= (b.lo[a] <= middle[a] + fudge_ ? 1 : 0) << a;
        upper |= (b.hi[a] >= middle[a] - fudge_ ? 1 : 0) << a;
    }
    // Per axis, the children taking the upper half (bit a of c set) and the lower.
    constexpr int kUpper[3] = {0xAA, 0xCC, 0xF0};
    int reached = 0xFF;
    for (int a = 0; a < 3; ++a) {
        const int allowed = (((upper >> a) & 1) != 0 ? kUpper[a] : 0) |
                            (((lower >> a) & 1) != 0 ? (~kUpper[a] & 0xFF) : 0);
        reached &= allowed;
    }
    return reached;
}

bool OctreeFill::touches(std::uint32_t polygon, const OctreeCell& child) const {
    // A child holding one of the corners certainly touches the polygon; only the others need the
    // exact test (for a small polygon across one midplane, none does).
    const Box3 box = cell_box(child).grown(fudge_);
    const Polygon& p = scene_.polygons[polygon];
    for (std::uint32_t k = 0; k < p.corner_count; ++k) {
        if (box.contains(scene_.corner_position(p, k))) {
            return true;
        }
    }
    return polygon_overlaps_box(scene_, polygon, box);
}

void OctreeFill::split(const OctreeCell& cell, const std::vector<std::uint32_t>& polygons,
                       std::array<std::vector<std::uint32_t>, 8>& children) const {
    for (auto& child : children) {
        child.clear();
    }
    double middle[3];
    for (int a = 0; a < 3; ++a) {
        middle[a] = tree_.lattice(a, cell.origin[a] + cell.size / 2);
    }
    // Deep in the tree a node's polygons lie scattered through memory, so their boxes and
    // records are fetched some steps ahead, their corner indices a few steps later (they need the
    // record) and the corners' positions later still. Only the timing changes, never the result.
    constexpr std::size_t kAhead = 16;
    constexpr std::size_t kCornerAhead = 8;
    constexpr std::size_t kPositionAhead = 3;
    const std::size_t count = polygons.size();
    for (std::size_t i = 0; i < count; ++i) {
        if (i + kAhead < count) {
            const std::uint32_t later = polygons[i + kAhead];
            // A box (48 bytes) or a record may straddle two cache lines: fetch both ends.
            const char* box = reinterpret_cast<const char*>(&bounds_[later]);
            prefetch(box);
            prefetch(box + sizeof(Box3) - 1);
            const char* record = reinterpret_cast<const char*>(&scene_.polygons[later]);
            prefetch(record);
            prefetch(record + offsetof(Polygon, normal) + sizeof(Vec3) - 1);
        }
        if (i + kCornerAhead < count) {
            const Polygon& later = scene_.polygons[polygons[i + kCornerAhead]];
            prefetch(&scene_.corners[later.first_corner]);
        }
        if (i + kPositionAhead < count) {
            const Polygon& later = scene_.polygons[polygons[i + kPositionAhead]];
            const std::uint32_t n = std::min<std::uint32_t>(later.corner_count, 4);
            for (std::uint32_t k = 0; k < n; ++k) {
                prefetch(&scene_.positions[scene_.corners[later.first_corner + k]]);
            }
        }
        const std::uint32_t id = polygons[i];
        const int reached = children_reached(id, middle);
        if (reached != 0 && (reached & (reached - 1)) == 0) {
            // Within one child's half on every axis: no exact test needed.
            children[std::countr_zero(static_cast<unsigned>(reached))].push_back(id);
            continue;
        }
        for (int c = 0; c < 8; ++c) {
            if (((reached >> c) & 1) != 0 && touches(id, cell.child(c))) {
                children[c].push_back(id);
            }
        }
    }
}

}  // namespace rt
