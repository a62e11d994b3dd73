// What the adaptive-sampling study prints: every plan's cost and error, and adaptive against
// uniform sampling at equal cost and at equal error, seed by seed.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "study_scene.h"

namespace rt::bench {

struct Measured {
    SamplingPlan plan;
    std::uint64_t seed = 0;
    Spent spent;
    double error = 0.0;  ///< RMS, display levels, against the reference
};

std::string describe(const SamplingPlan& plan);

/// Each plan: rays, samples and eye rays per pixel (means over seeds) and the error per seed.
void print_plans(std::ostream& out, const std::vector<Measured>& runs, double pixels);

/// Adaptive against uniform, per seed: error at equal rays, rays at equal error.
void print_comparisons(std::ostream& out, const std::vector<Measured>& runs);

/// One CSV row per plan and seed.
void write_csv(std::ostream& out, const std::vector<Measured>& runs, double pixels);

}  // namespace rt::bench
