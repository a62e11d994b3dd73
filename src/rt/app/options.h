// Everything a program can be told on its command line, in the library's own settings: the switch
// table (switch_table.cpp) writes the reading dialect, the shading and sampling settings, the
// intersection method and the display mapping directly, and run() hands them on as they are.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "rt/accel/accel_settings.h"
#include "rt/image/film.h"
#include "rt/image/picture_parts.h"
#include "rt/scene/read/dialect.h"
#include "rt/shading/shading_settings.h"

namespace rt {

/// -Oi and -O1: the earliest versions of the raytracer (docs/rendering.md), applied over the
/// shading settings by earliest_version() whatever the order of the switches.
enum class EarlyVersion { None, OldIllumination, OldVersion };

struct Options {
    // --- what to read (manual 2.2 to 2.5) ---------------------------------------------------
    std::string scene;           ///< the SCENE argument, with or without .scn
    std::string model;           ///< --model FILE: a model file rendered without a .scn
    ReaderDialect dialect;       ///< -Df -Dp -Of -Po -Pt -M -R -V
    bool trace_parsing = false;  ///< -df

    // --- shading and sampling ---------------------------------------------------------------
    ShadingSettings shading;                  ///< -A -T -D. -Po -S -C -W -F -X -I -Ot, --seed
    EarlyVersion early = EarlyVersion::None;  ///< -Oi -O1
    std::optional<double> crease_angle;       ///< -E (radians): sharp breaks in smooth shading
    bool scale_weights = false;               ///< -K

    // --- the film -----------------------------------------------------------------------------
    DisplayMapping display;         ///< -m -c
    std::optional<int> start_line;  ///< -L: draw only from this line up

    // --- the intersection method (manual part three) -------------------------------------------
    /// --accel -od -tv -ol -ss -on -of -op -De --zbuffer, and the debugging switches -ds -dsp -dso
    /// -dl -doo -dof -de; what they leave unset, the scene header decides.
    AcceleratorStackSettings accel;

    // --- output -------------------------------------------------------------------------------
    std::vector<std::string> outputs;  ///< --output FILE (repeatable); format from the extension
    bool no_gro = false;               ///< -n
    std::optional<PicturePart> tile;   ///< --tile I/N: render part I of N into a part file

    // --- what else to do or print ---------------------------------------------------------------
    bool wireframe_only = false;            ///< -w
    bool draw_octree = false;               ///< -oo
    bool profile = false;                   ///< -p
    bool random_rays = false;               ///< -r
    bool print_columns = false;             ///< -dc
    bool debug_octree_interactive = false;  ///< -doi
    bool debug_color = false;               ///< -dd
    bool debug_chi_square = false;          ///< -dx

    // --- the program itself (long options) ----------------------------------------------------
    bool show_help = false;                ///< --help
    bool show_version = false;             ///< --version
    bool show_usage = false;               ///< no arguments at all
    bool quiet = false;                    ///< --quiet: no progress, no notes
    int threads = 0;                       ///< --threads (0: all cores)
    bool no_window = false;                ///< --no-window: never open a window, even on a display
    std::string resume;                    ///< --resume FILE.gro: continue that interrupted render
    std::optional<double> max_memory_gib;  ///< --max-memory: instead of the memory available

    /// The switches exactly as given (not the scene, not long options), for the .gro header.
    std::vector<std::string> given_switches;
    /// The scene and every switch that decides the picture, each as its words on the command
    /// line ({"-m", "2.0"}, {"--seed=7"}): what a .gro records for --resume.
    std::vector<std::vector<std::string>> render_arguments;
};

}  // namespace rt
