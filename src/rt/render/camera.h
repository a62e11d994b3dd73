// The renderer's camera: the pinhole view of the .scn file (rt/scene/pinhole_view.h), which the
// z-buffer shares so that both compute the very same eye rays.
#pragma once

#include "rt/scene/pinhole_view.h"

namespace rt {

using Camera = PinholeView;

}  // namespace rt
