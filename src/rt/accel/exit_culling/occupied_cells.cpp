#include "rt/accel/exit_culling/occupied_cells.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "rt/accel/parallel_parts.h"

namespace rt {

namespace {

// Interleaves the low 6 bits of x, y, z: neighbouring cells stay together when the tree halves
// the list, which keeps its boxes small.
std::uint32_t morton(int x, int y, int z) {
    std::uint32_t code = 0;
    for (int bit = 0; bit < 6; ++bit) {
        code |= ((static_cast<std::uint32_t>(x) >> bit) & 1u) << (3 * bit);
        code |= ((static_cast<std::uint32_t>(y) >> bit) & 1u) << (3 * bit + 1);
        code |= ((static_cast<std::uint32_t>(z) >> bit) & 1u) << (3 * bit + 2);
    }
    return code;
}

}  // namespace

CullingFrame culling_frame(const Scene& scene) {
    CullingFrame frame;
    frame.positions = scene.bounds();
    const double diagonal = length(frame.positions.extent());
    const double magnitude = frame.positions.magnitude();
    frame.far_limit = 100.0 * diagonal;
    // The ray-polygon test rounds to within about 1e-15 of the distance from a ray origin (up to
    // 101 diagonals from a corner) and of the coordinates; polygon_reach() asks for 1e-13.
    frame.rounding = 2e-11 * diagonal + 1e-13 * magnitude;
    // Far above that and above the rounding of entry points and cell lookups, far below a cell.
    frame.margin = std::max(1e-6 * diagonal + 1e-12 * magnitude, 1e-200);
    return frame;
}

OccupiedCells::OccupiedCells(const CullingFrame& frame, const ReachSource& reaches, int resolution,
                             int threads)
    : frame_(frame), resolution_(resolution) {
    if (resolution < 1 || resolution > 64) {
        throw std::invalid_argument("exit culling grid resolution must be 1..64");
    }
    // Each part its own box, joined after (a union is exact and order-free).
    std::vector<Box3> parts(static_cast<std::size_t>(std::max(threads, 1)));
    run_in_parts(reaches.count(), threads, [&](std::size_t begin, std::size_t end, int part) {
        for (std::size_t id = begin; id < end; ++id) {
            parts[static_cast<std::size_t>(part)].add(reaches(id).all());
        }
    });
    for (const Box3& part : parts) {
        world_.add(part);
    }
    if (world_.empty()) {
        world_ = frame_.positions;
    }
    world_ = world_.grown(frame_.margin);
    cell_size_ = world_.extent() / resolution_;
    top_cell_ = resolution_ - 1;
    for (int axis = 0; axis < 3; ++axis) {
        inverse_cell_size_[axis] = cell_size_[axis] > 0.0 ? 1.0 / cell_size_[axis] : 0.0;
        for (int index = 0; index <= resolution_; ++index) {
            boundaries_[axis].push_back(boundary(axis, index));
        }
    }

    std::vector<Box3> cells(static_cast<std::size_t>(resolution_) * resolution_ * resolution_);
    fill(reaches, cells, threads);
    std::vector<Box3> leaves;
    std::vector<std::uint32_t> codes;
    for (int cell = 0; cell < static_cast<int>(cells.size()); ++cell) {
        if (!cells[cell].empty()) {
            leaves.push_back(cells[cell]);
            const int x = cell % resolution_;
            const int y = (cell / resolution_) % resolution_;
            codes.push_back(morton(x, y, cell / (resolution_ * resolution_)));
        }
    }
    std::vector<std::size_t> order(leaves.size());
    for (std::size_t i = 0; i < order.size(); ++i) {
        order[i] = i;
    }
    std::sort(order.begin(), order.end(), [&](auto a, auto b) { return codes[a] < codes[b]; });
    std::vector<Box3> sorted;
    sorted.reserve(order.size());
    for (const std::size_t i : order) {
        sorted.push_back(leaves[i]);
    }
    occupied_ = sorted.size();
    tree_.reserve(2 * sorted.size());
    if (!sorted.empty()) {
        tree_.push_back({});
        build_node(sorted, 0, sorted.size(), 0);
    }
}

void OccupiedCells::cell_range(const Box3& box, double grow, int first[3], int last[3]) const {
    for (int axis = 0; axis < 3; ++axis) {
        int f = std::max(axis_cell(axis, box.lo[axis]) - 1, 0);
        int l = std::min(axis_cell(axis, box.hi[axis]) + 1, resolution_ - 1);
        // The extra cell each way meets the box only near a boundary. Where a cell's box (grown
        // as Box3::grown grows it) ends before the box starts, or starts after it ends, their
        // intersection is empty: leaving it out changes no piece, and a small polygon's reach
        // then visits one to eight cells instead of 27.
        const std::vector<double>& b = boundaries_[axis];
        while (f < l && b[static_cast<std::size_t>(f) + 1] + grow < box.lo[axis]) {
            ++f;
        }
        while (l > f && b[static_cast<std::size_t>(l)] - grow > box.hi[axis]) {
            --l;
        }
        first[axis] = f;
        last[axis] = l;
    }
}

// Part 0 fills `cells`, the others their own copies, joined after: a union of boxes is exact and
// does not depend on the order.
void OccupiedCells::fill(const ReachSource& reaches, std::vector<Box3>& cells, int threads) const {
    const int parts = std::max(threads, 1);
    std::vector<std::vector<Box3>> copies(static_cast<std::size_t>(parts - 1),
                                          std::vector<Box3>(cells.size()));
    run_in_parts(reaches.count(), parts, [&](std::size_t begin, std::size_t end, int part) {
        std::vector<Box3>& mine = part == 0 ? cells : copies[static_cast<std::size_t>(part - 1)];
        for (std::size_t id = begin; id < end; ++id) {
            const PolygonReach reach = reaches(id);
            if (!reach.box.empty()) {
                add_reach(reach, mine);
            }
        }
    });
    for (const std::vector<Box3>& copy : copies) {
        for (std::size_t cell = 0; cell < cells.size(); ++cell) {
            if (!copy[cell].empty()) {
                cells[cell].add(copy[cell]);
            }
        }
    }
}

// Grows each cell the reach's slab meets by the part of the reach's box inside that cell.
void OccupiedCells::add_reach(const PolygonReach& reach, std::vector<Box3>& cells) const {
    int first[3];
    int last[3];
    cell_range(reach.box, 0.0, first, last);
    for (int z = first[2]; z <= last[2]; ++z) {
        for (int y = first[1]; y <= last[1]; ++y) {
            for (int x = first[0]; x <= last[0]; ++x) {
                const int cell = x + resolution_ * (y + resolution_ * z);
                const Box3 piece = intersection(reach.box, cell_box(x, y, z));
                if (!piece.empty() && slab_meets_box(reach, piece)) {
                    cells[cell].add(piece);
                }
            }
        }
    }
}

void OccupiedCells::build_node(const std::vector<Box3>& leaves, std::size_t begin, std::size_t end,
                               std::size_t slot) {
    Node node;
    for (std::size_t i = begin; i < end; ++i) {
        node.box.add(leaves[i]);
    }
    if (end - begin > 1) {
        // The two children sit side by side, so a node needs only the first one's index.
        node.first_child = static_cast<std::int32_t>(tree_.size());
        tree_.push_back({});
        tree_.push_back({});
        const std::size_t middle = begin + (end - begin) / 2;
        build_node(leaves, begin, middle, static_cast<std::size_t>(node.first_child));
        build_node(leaves, middle, end, static_cast<std::size_t>(node.first_child) + 1);
    }
    tree_[slot] = node;
}

double OccupiedCells::boundary(int axis, int index) const {
    if (index <= 0) {
        return world_.lo[axis];
    }
    if (index >= resolution_) {
        return world_.hi[axis];
    }
    return world_.lo[axis] + index * cell_size_[axis];
}

Box3 OccupiedCells::cell_box(int cell) const {
    return cell_box(cell % resolution_, (cell / resolution_) % resolution_,
                    cell / (resolution_ * resolution_));
}

}  // namespace rt
