// A film described in words, for `show --info`.
#pragma once

#include <string>

#include "rt/image/film.h"

namespace rt {

/// Several "name  value" lines: view size, window, rows finished, display mapping, scene,
/// switches, program and creation time.
std::string film_summary(const Film& film);

}  // namespace rt
