// A film described in words, for `show --info`.
#pragma once

#include <string>

#include "rt/image/film.h"
#include "rt/image/gro_header.h"

namespace rt {

/// Several "name  value" lines: view size, window, rows finished, display mapping, scene,
/// switches, program and creation time.
std::string film_summary(const Film& film);

/// The same lines from a .gro header alone (read_gro_header_only), for pictures too large to load.
std::string header_summary(const GroHeader& header);

}  // namespace rt
