// One surface attribute of the Attributes file (manual 2.3).
#pragma once

#include "rt/core/error.h"
#include "rt/core/rgb.h"

namespace rt {

struct Attribute {
    Rgb color;                            ///< red, green, blue intensities, 0..1
    double specular_exponent = 2.0;       ///< "pow": cos^n law for specular reflection
    double transmit_exponent = 2.0;       ///< "tpow": cos^n law for specular refraction
    double emission = 0.0;                ///< weights: emitted,
    double ambient = 0.0;                 ///<   ambient,
    double diffuse = 0.0;                 ///<   diffusely reflected,
    double specular = 0.0;                ///<   specularly reflected,
    double transmission = 0.0;            ///<   transmitted
    Rgb refraction_index{1.0, 1.0, 1.0};  ///< one index repeated, or three with -R
    double reflect_cone_degrees = 0.0;    ///< distributed reflection: cone angle theta
    double reflect_cone_exponent = 0.0;   ///<   and its cos^n exponent
    double refract_cone_degrees = 0.0;    ///< distributed refraction: cone angle theta
    double refract_cone_exponent = 0.0;   ///<   and its cos^n exponent
    long index = 0;                       ///< the number .scn files use to refer to it
    SourceLocation where;                 ///< the line it was read from

    bool is_emissive() const { return emission > 0.0; }
    /// Opaque surfaces stop shadow feelers; the manual's "not opaque" means it transmits.
    bool is_opaque() const { return transmission <= 0.0; }
};

}  // namespace rt
