#include "rt/wireframe/wire_segments.h"

#include <cstdint>

namespace rt {

namespace {

// The edges of a box, as pairs of its corners (Box3::corner numbering: bit 0 x, 1 y, 2 z).
constexpr int kBoxEdges[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                                  {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};

void add_box_edges(const Box3& box, std::vector<WireSegment>& out) {
    for (const auto& edge : kBoxEdges) {
        out.push_back({box.corner(edge[0]), box.corner(edge[1])});
    }
}

// Walks the tree keeping each node's lattice corner and side, as the listing (-doo) does; the
// boxes come from OctreeTree::lattice, the formula the build and the walk share.
void add_leaves(const OctreeTree& tree, std::uint32_t index, const std::int64_t origin[3],
                std::int64_t size, std::vector<WireSegment>& out) {
    const OctreeNode& node = tree.nodes[index];
    if (node.is_leaf()) {
        Box3 box;
        for (int a = 0; a < 3; ++a) {
            box.lo[a] = tree.lattice(a, origin[a]);
            box.hi[a] = tree.lattice(a, origin[a] + size);
        }
        add_box_edges(box, out);
        return;
    }
    const std::int64_t half = size / 2;
    for (std::uint32_t c = 0; c < 8; ++c) {
        std::int64_t child[3];
        for (int a = 0; a < 3; ++a) {
            child[a] = origin[a] + (((c >> a) & 1) != 0 ? half : 0);
        }
        add_leaves(tree, node.first + c, child, half, out);
    }
}

}  // namespace

std::vector<WireSegment> polygon_edges(const Scene& scene) {
    std::vector<WireSegment> edges;
    edges.reserve(scene.corners.size());
    for (const Polygon& p : scene.polygons) {
        for (std::uint32_t k = 0; k < p.corner_count; ++k) {
            edges.push_back(
                {scene.corner_position(p, k), scene.corner_position(p, (k + 1) % p.corner_count)});
        }
    }
    return edges;
}

std::vector<WireSegment> polygon_normals(const Scene& scene, double length) {
    std::vector<WireSegment> normals;
    if (length == 0.0) {
        return normals;
    }
    normals.reserve(scene.polygons.size());
    for (const Polygon& p : scene.polygons) {
        Vec3 centre;
        for (std::uint32_t k = 0; k < p.corner_count; ++k) {
            centre += scene.corner_position(p, k);
        }
        centre = centre / static_cast<double>(p.corner_count);
        normals.push_back({centre, centre + p.normal * length});
    }
    return normals;
}

std::vector<WireSegment> octree_leaf_edges(const OctreeTree& tree) {
    std::vector<WireSegment> edges;
    if (tree.nodes.empty()) {
        return edges;
    }
    const std::int64_t origin[3] = {0, 0, 0};
    add_leaves(tree, 0, origin, std::int64_t{1} << tree.depth, edges);
    return edges;
}

}  // namespace rt
