// The adaptive-sampling study's command line: its own options, and rt's switches for the rest.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "rt/image/film.h"

#include "study_scene.h"
#include <CLI/CLI.hpp>

namespace rt::bench {

struct StudyArguments {
    int seeds = 6;                        ///< --seeds N: seeds 1..N for every plan
    SamplingPlan reference{8, 8, false};  ///< --reference NxN: -Dx at a high resolution
    int reference_renders = 4;            ///< --reference-renders M: seeds 1001..1000+M
    std::optional<PixelRect> window;      ///< --window l,t,r,b
    std::vector<SamplingPlan> uniform;    ///< --uniform NxM,...: -Dx plans
    std::vector<SamplingPlan> adaptive;   ///< --adaptive NxM@var,...: -Xp and -Xr var
    std::optional<std::string> csv;       ///< --csv FILE: one row per plan and seed
    std::vector<std::string> rt_args;     ///< SCENE and rt's switches
};

/// Declares the study's options on app, writing into out (--name VALUE or --name=VALUE;
/// --uniform and --adaptive add up when repeated), and lets app keep every other argument, in
/// order, for rt::parse_command_line (take them with app.remaining() after parsing).
void add_study_options(CLI::App& app, StudyArguments& out);

}  // namespace rt::bench
