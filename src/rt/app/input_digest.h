// A digest of everything a render read: the contents of the scene's files (.scn, Attributes,
// shape and surface files, texture maps) and the pictures its texture maps name. A .gro records
// it so that --resume can refuse a scene that changed since the render began.
#pragma once

#include <string>

#include "rt/scene/scene.h"

namespace rt {

/// "fnv1a64:" and 16 hex digits: FNV-1a over each file's name and bytes, in the order read, and
/// each texture picture's size and pixels. Not a cryptographic hash: it notices edits, not
/// forgeries.
std::string input_digest(const Scene& scene);

}  // namespace rt
