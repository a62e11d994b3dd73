// The product's version, from the build.
#pragma once

#include <string_view>

namespace rt {

inline constexpr std::string_view kVersion = "0.1.0";

}  // namespace rt
