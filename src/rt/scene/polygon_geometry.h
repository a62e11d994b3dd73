// Plane normals and degeneracy of polygon loops, for the readers' assembly step.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

#include "rt/core/vec3.h"

namespace rt {

/// Newell's normal of the loop vertices[loop[0]], vertices[loop[1]], ...: the right-hand-rule
/// normal, of length twice the area. Works for any planar (or nearly planar) loop.
Vec3 newell_normal(std::span<const std::uint32_t> loop, std::span<const Vec3> vertices);

/// Why a loop cannot be a polygon: "fewer than 3 distinct corners", "zero area", or empty if it
/// can.
std::string_view degeneracy(std::span<const std::uint32_t> loop, std::span<const Vec3> vertices,
                            const Vec3& newell);

}  // namespace rt
