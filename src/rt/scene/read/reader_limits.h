// Sane limits every scene reader checks before it trusts a count or allocates (docs/formats.md).
#pragma once

#include <cmath>
#include <cstdint>

#include "rt/core/vec3.h"

namespace rt {

/// Input files larger than this are refused before they are read.
inline constexpr std::uintmax_t kMaxInputFileBytes = std::uintmax_t{1} << 30;
/// Vertices, edges, polygons, attributes or shapes in one file.
inline constexpr std::int64_t kMaxItemsPerFile = 50'000'000;
/// Edges of one filetype-0 polygon, corners of one Phigs+ fill area.
inline constexpr std::int64_t kMaxEdgesPerPolygon = 100'000;
inline constexpr std::int64_t kMaxEntities = 1'000'000;
inline constexpr std::int64_t kMaxSurfacesPerEntity = 1'000'000;
/// Texture-mapped surfaces (-V) in a .scn.
inline constexpr std::int64_t kMaxTexturedSurfaces = 1'000'000;
/// Points of one texture-mapped surface's grid, (rows + 1) x (columns + 1).
inline constexpr std::int64_t kMaxGridPoints = kMaxItemsPerFile;
/// Optical centres of one texture map.
inline constexpr std::int64_t kMaxOpticalCentres = 1'000'000;
/// Each side of the view area, in pixels.
inline constexpr int kMaxViewSide = 16384;
inline constexpr int kMaxSampleResolution = 64;
inline constexpr int kMaxRayDepth = 64;
/// SEADS voxels a side (header sptncde): SEADS builds at most 2^25 voxels (seads_grid.h), 322
/// a side. And the octree depth (header octr).
inline constexpr int kMaxSeadsVoxels = 322;
inline constexpr int kMaxOctreeDepth = 20;
/// The largest |coordinate| of a placed vertex, a shape's point, the eye and the look point, and
/// the largest screen distance and shape radius: the world's extent, voxel sizes and Embree's float
/// rays stay finite and keep a useful precision.
inline constexpr double kMaxCoordinate = 1e15;
/// Whether every coordinate of `p` is within kMaxCoordinate (NaN is not).
inline bool within_coordinate_range(const Vec3& p) {
    return std::fabs(p.x) <= kMaxCoordinate && std::fabs(p.y) <= kMaxCoordinate &&
           std::fabs(p.z) <= kMaxCoordinate;
}
/// The screen distance must be more than this times the eye point's largest |coordinate| (or 1
/// when that is smaller): eye rays start on the screen, aimed away from the eye.
inline constexpr double kLeastScreenDistance = 1e-6;
/// The largest |value| of an attribute's colour channels and weights (e a d s t): a light or a
/// surface can be bright, but not so bright that a few bounces leave the float range.
inline constexpr double kMaxIntensity = 1e6;

}  // namespace rt
