// Builds the intersection method the settings name.
#pragma once

#include <memory>

#include "rt/accel/accel_settings.h"
#include "rt/accel/accelerator.h"

namespace rt {

/// The scene must outlive the result. Throws NotImplementedError for a method not built in (an
/// Embree backend without Embree) and UsageError for settings it cannot honour.
std::unique_ptr<Accelerator> make_accelerator(const Scene& scene, const AccelSettings& settings);

}  // namespace rt
