// The rays every intersection method traces in the lab: the same ones for all.
#pragma once

#include <cstdint>
#include <vector>

#include "rt/accel/accelerator.h"
#include "rt/core/ray.h"
#include "rt/scene/scene.h"

namespace rt::lab {

constexpr int kImageWidth = 512;
constexpr int kImageHeight = 400;

/// Coherent rays: one per pixel of a 512x400 pinhole camera looking at the middle of the scene's
/// box from outside it, the box filling most of the view.
std::vector<Ray> camera_rays(const Scene& scene);

/// The rays eight to a packet: `width` > 0 takes them as rows of that many pixels and makes
/// packets of 4x2 pixels (rows of a multiple of 4, an even count of rows); 0 takes them in order.
std::vector<RayPacket> packets_of(const std::vector<Ray>& rays, int width);

/// Incoherent rays: origins uniform in the scene's box doubled about its middle, directions
/// uniform on the sphere. Reproducible from `seed`.
std::vector<Ray> random_rays(const Scene& scene, std::size_t count, std::uint64_t seed = 7);

}  // namespace rt::lab
