// The file-format variants the command line selects (manual 2.1-2.5): a plain struct the readers
// consult, so that no reader ever looks at argv.
#pragma once

namespace rt {

struct ReaderDialect {
    bool attributes_inline = false;   ///< -Df (or -Of): attributes in the .scn, not a file
    bool no_power_fields = false;     ///< -Dp (or -Of): pow and tpow absent, taken as 2.0
    bool smooth_shade_field = false;  ///< -Po or -Pt: a fourth number before each surface name
    bool marks = false;               ///< -M: polygons carry mark and shape index; $@shapes line
    bool rgb_refraction = false;      ///< -R: three indices of refraction per attribute
    bool textures = false;            ///< -V: texture-mapped surfaces follow the entities
};

}  // namespace rt
