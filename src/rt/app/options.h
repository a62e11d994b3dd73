// Everything a program can be told on its command line. Filled by the switch table
// (switch_table.cpp); the library itself sees only the plain settings derived from it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "rt/scene/dialect.h"

namespace rt {

enum class SpecularModel {
    Phong,
    PhongGeometric,
    TorranceSparrowGaussian,
    TorranceSparrowBeckmann
};
enum class HighlightColor { Default, ObjectAttenuates, LightOnly, Fresnel };
enum class WarnLight { None, Rogers, Conical, Thibadeau };
enum class PhongShading { None, Opaque, Transparent };

struct Options {
    // --- what to read and write -----------------------------------------------------------
    std::string scene;                 ///< the SCENE argument, with or without .scn
    std::vector<std::string> outputs;  ///< --output FILE (repeatable); format from the extension
    bool no_gro = false;               ///< -n
    ReaderDialect dialect;             ///< -Df -Dp -Of -Po -Pt -M -R -V
    PhongShading phong = PhongShading::None;  ///< -Po / -Pt
    bool trace_parsing = false;               ///< -df

    // --- display mapping --------------------------------------------------------------------
    double display_multiplier = 1.0;  ///< -m
    bool clip_intensity = true;       ///< -c toggles it off

    // --- illumination -----------------------------------------------------------------------
    SpecularModel specular = SpecularModel::Phong;       ///< -Sp -Sg -Stg -Stb
    double microfacet_slope = 1.0;                       ///< the m of -Stg / -Stb
    HighlightColor highlight = HighlightColor::Default;  ///< -Co -Ci -Cf
    WarnLight warn = WarnLight::None;                    ///< -Wr -Wc -Wt
    double warn_parameter = 0.0;                         ///< the angle of -Wc, the distance of -Wt
    double attenuation_distance = 200.0;                 ///< -A d,c: divide by dist/d + c
    double attenuation_constant = 1.0;
    bool specular_refraction_feelers = false;  ///< -T
    bool disable_distribution = false;         ///< -Dd
    bool disable_adaptive = false;             ///< -Dx
    bool disable_exit_culling = false;         ///< -De
    bool feelers_stop_at_transparent = false;  ///< -Dt
    bool disable_attenuation = false;          ///< -Da
    bool disable_light_attenuation = false;    ///< -Dl (the manual prints -DI)
    bool disable_shadow_feelers = false;       ///< -Ds
    bool disable_reflection = false;           ///< -Dr
    bool single_sided_emitters = false;        ///< -Db
    bool old_intersection_test = false;        ///< -Ot
    bool old_illumination = false;             ///< -Oi
    bool old_version = false;                  ///< -O1
    bool scale_weights = false;                ///< -K
    bool illuminate_distributed = false;       ///< -I
    std::optional<int> start_line;             ///< -L
    std::optional<double> crease_angle;        ///< -E (radians)
    std::optional<double> fuzzy_distangle;     ///< -F distangle,distfac
    double fuzzy_distfac = 0.0;
    std::optional<double> pixel_stop_probability;  ///< -Xp prob,var
    double pixel_stop_variance = 0.2;
    std::optional<double> ray_stop_probability;  ///< -Xr prob,var
    double ray_stop_variance = 0.2;

    // --- spatial encoding (manual part three) -----------------------------------------------
    bool wireframe_only = false;                ///< -w
    std::optional<int> terminate_after_voxels;  ///< -tv
    std::optional<int> octree_depth;            ///< -od
    bool draw_octree = false;                   ///< -oo
    std::optional<int> octlist_power;           ///< -ol
    bool accept_near_hits = false;              ///< -on
    bool no_fudge = false;                      ///< -of
    bool new_fillplane = false;                 ///< -op
    std::optional<int> seed_size_power;         ///< -ss
    bool profile = false;                       ///< -p
    bool random_rays = false;                   ///< -r
    std::optional<std::string> accel;           ///< --accel NAME: overrides the scene header
    bool zbuffer_first_hits = false;            ///< --zbuffer: eye rays from an item buffer

    // --- debugging --------------------------------------------------------------------------
    bool print_columns = false;             ///< -dc
    bool debug_strike = false;              ///< -ds
    bool debug_strike_print = false;        ///< -dsp
    bool debug_strike_oct = false;          ///< -dso
    bool debug_intersections = false;       ///< -dl
    bool debug_octree_output = false;       ///< -doo
    bool debug_octree_interactive = false;  ///< -doi
    bool debug_fillplane = false;           ///< -dof
    bool debug_color = false;               ///< -dd
    bool debug_chi_square = false;          ///< -dx
    bool debug_exit_culling = false;        ///< -de

    // --- the program itself (long options) ----------------------------------------------------
    bool show_help = false;     ///< --help
    bool show_version = false;  ///< --version
    bool show_usage = false;    ///< no arguments at all
    bool quiet = false;         ///< --quiet: no progress, no notes
    std::uint64_t seed = 0;     ///< --seed
    int threads = 0;            ///< --threads (0: all cores)

    /// The switches exactly as given (not the scene, not long options), for the .gro header.
    std::vector<std::string> given_switches;
};

}  // namespace rt
