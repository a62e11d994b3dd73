// One step of the top-down build: split a range of references in two by the binned surface area
// heuristic, or decide that it is cheaper as a leaf.
#pragma once

#include <cstdint>
#include <span>

#include "rt/accel/bvh/polygon_references.h"

namespace rt::bvh {

struct ReferenceRange {
    std::uint32_t begin = 0;
    std::uint32_t end = 0;
    Box box;                      ///< of the references' boxes
    Box centroids;                ///< of the references' box centres
    std::uint32_t triangles = 0;  ///< fan triangles in the range
    std::uint32_t size() const { return end - begin; }
};

struct SplitDecision {
    bool leaf = true;
    ReferenceRange left;
    ReferenceRange right;
};

/// Most fan triangles in a leaf (unless one polygon has more): two packets.
constexpr std::uint32_t kMaxLeafTriangles = 8;

/// Splits `range` (reordering refs inside it) or says it is a leaf. `by_median` forces an object
/// median split on the longest centroid axis, which halves the range: the builder uses it past a
/// depth limit so that the tree, and the traversal's stack, stay shallow. A big range is binned by
/// `threads` threads; the decision does not depend on their number.
SplitDecision split_range(std::span<PolygonReference> refs, const ReferenceRange& range,
                          bool by_median, unsigned threads = 1);

/// The boxes and triangle count of refs[begin, end).
ReferenceRange make_range(std::span<const PolygonReference> refs, std::uint32_t begin,
                          std::uint32_t end);

}  // namespace rt::bvh
