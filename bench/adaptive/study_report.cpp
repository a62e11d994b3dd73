#include "study_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <optional>

#include "error_curve.h"

namespace rt::bench {

namespace {

std::string format(const char* pattern, double value) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, pattern, value);
    return buffer;
}

// An adaptive plan's stop rule: "@var", "@pvar/rvar", with ":prob" unless the default.
std::string rule_of(const SamplingPlan& plan) {
    std::string rule = format("@%g", plan.pixel_variance);
    if (plan.ray_variance != plan.pixel_variance) {
        rule += format("/%g", plan.ray_variance);
    }
    if (plan.probability != SamplingPlan{}.probability) {
        rule += format(":%g", plan.probability);
    }
    return rule;
}

std::vector<std::uint64_t> seeds_of(const std::vector<Measured>& runs) {
    std::vector<std::uint64_t> seeds;
    for (const Measured& m : runs) {
        if (std::find(seeds.begin(), seeds.end(), m.seed) == seeds.end()) {
            seeds.push_back(m.seed);
        }
    }
    return seeds;
}

// The plans in the order first run.
std::vector<std::string> plans_of(const std::vector<Measured>& runs) {
    std::vector<std::string> plans;
    for (const Measured& m : runs) {
        const std::string name = describe(m.plan);
        if (std::find(plans.begin(), plans.end(), name) == plans.end()) {
            plans.push_back(name);
        }
    }
    return plans;
}

const Measured* find(const std::vector<Measured>& runs, const std::string& plan,
                     std::uint64_t seed) {
    for (const Measured& m : runs) {
        if (m.seed == seed && describe(m.plan) == plan) {
            return &m;
        }
    }
    return nullptr;
}

// The lower envelope of one seed's uniform plans, or of its adaptive plans with one stop rule.
std::vector<CurvePoint> envelope(const std::vector<Measured>& runs, std::uint64_t seed,
                                 const std::string& adaptive_rule = "") {
    std::vector<CurvePoint> points;
    for (const Measured& m : runs) {
        const bool wanted = adaptive_rule.empty()
                                ? !m.plan.adaptive
                                : m.plan.adaptive && rule_of(m.plan) == adaptive_rule;
        if (m.seed == seed && wanted) {
            points.push_back({static_cast<double>(m.spent.rays), m.error});
        }
    }
    return lower_envelope(points);
}

// One row: a label, a figure per seed ("-" where none), and their geometric mean.
void print_ratio_row(std::ostream& out, const std::string& label,
                     const std::vector<std::optional<double>>& ratios) {
    out << "  " << label;
    for (std::size_t pad = label.size(); pad < 22; ++pad) {
        out << ' ';
    }
    double log_sum = 0.0;
    int count = 0;
    double lowest = std::numeric_limits<double>::infinity();
    double highest = 0.0;
    for (const std::optional<double>& r : ratios) {
        out << (r ? format("%7.2f", *r) : std::string("      -"));
        if (r) {
            log_sum += std::log(*r);
            ++count;
            lowest = std::min(lowest, *r);
            highest = std::max(highest, *r);
        }
    }
    if (count > 0) {
        out << "   " << format("%5.2f", std::exp(log_sum / count)) << " (" << format("%.2f", lowest)
            << "-" << format("%.2f", highest) << ")";
    }
    out << '\n';
}

void print_seed_header(std::ostream& out, const std::string& title,
                       const std::vector<std::uint64_t>& seeds) {
    out << title << '\n' << "  plan                  ";
    for (const std::uint64_t s : seeds) {
        out << "  seed " << s;
    }
    out << "   geometric mean (range)\n";
}

}  // namespace

std::string describe(const SamplingPlan& plan) {
    std::string name = (plan.adaptive ? "adaptive " : "uniform ") + std::to_string(plan.nx) + "x" +
                       std::to_string(plan.ny);
    return plan.adaptive ? name + " " + rule_of(plan) : name;
}

void print_plans(std::ostream& out, const std::vector<Measured>& runs, double pixels) {
    const std::vector<std::uint64_t> seeds = seeds_of(runs);
    out << "Each plan: per pixel, the mean over seeds of every ray traced, of the samples (eye\n"
           "rays, the rays they spawn, probes) and of the eye rays; RMS error per seed.\n"
           "  plan                      rays  samples     eye";
    for (const std::uint64_t s : seeds) {
        out << "  seed " << s;
    }
    out << "    mean\n";
    for (const std::string& plan : plans_of(runs)) {
        const double runs_pixels = pixels * static_cast<double>(seeds.size());
        double rays = 0.0;
        double samples = 0.0;
        double eye = 0.0;
        double error = 0.0;
        std::string errors;
        for (const std::uint64_t s : seeds) {
            const Measured* m = find(runs, plan, s);
            rays += static_cast<double>(m->spent.rays) / runs_pixels;
            samples += static_cast<double>(m->spent.samples) / runs_pixels;
            eye += static_cast<double>(m->spent.eye) / runs_pixels;
            error += m->error / static_cast<double>(seeds.size());
            errors += format("%8.3f", m->error);
        }
        out << "  " << plan;
        for (std::size_t pad = plan.size(); pad < 22; ++pad) {
            out << ' ';
        }
        out << format("%8.1f", rays) << format("%9.1f", samples) << format("%8.2f", eye) << errors
            << format("%8.3f", error) << '\n';
    }
}

// One row per adaptive plan, one column per seed: ratio(run, uniform's envelope for its seed),
// empty where the ratio cannot be told.
template <typename Ratio>
void print_adaptive_ratios(std::ostream& out, const std::vector<Measured>& runs,
                           const std::vector<std::uint64_t>& seeds, Ratio ratio) {
    for (const std::string& plan : plans_of(runs)) {
        std::vector<std::optional<double>> ratios;
        for (const std::uint64_t s : seeds) {
            const Measured* m = find(runs, plan, s);
            if (!m->plan.adaptive) {
                break;
            }
            ratios.push_back(ratio(*m, envelope(runs, s)));
        }
        if (!ratios.empty()) {
            print_ratio_row(out, plan, ratios);
        }
    }
}

void print_comparisons(std::ostream& out, const std::vector<Measured>& runs) {
    const std::vector<std::uint64_t> seeds = seeds_of(runs);
    print_seed_header(out,
                      "\nAt equal rays: adaptive's error / uniform's (uniform's interpolated on "
                      "log-log axes between its resolutions)",
                      seeds);
    print_adaptive_ratios(out, runs, seeds, [](const Measured& m, const auto& uniform) {
        const std::optional<double> u = error_at_cost(uniform, static_cast<double>(m.spent.rays));
        return u ? std::optional<double>(m.error / *u) : std::nullopt;
    });
    print_seed_header(out,
                      "\nAt equal error: adaptive's rays / the rays uniform needs for adaptive's "
                      "error",
                      seeds);
    print_adaptive_ratios(out, runs, seeds, [](const Measured& m, const auto& uniform) {
        const std::optional<double> u = cost_for_error(uniform, m.error);
        return u ? std::optional<double>(static_cast<double>(m.spent.rays) / *u) : std::nullopt;
    });
    std::vector<std::string> rules;  // the stop rules run at two resolutions or more
    std::map<std::string, int> resolutions;
    for (const std::string& plan : plans_of(runs)) {
        const Measured* m = find(runs, plan, seeds.front());
        if (m->plan.adaptive && ++resolutions[rule_of(m->plan)] == 2) {
            rules.push_back(rule_of(m->plan));
        }
    }
    for (const std::string& rule : rules) {
        print_seed_header(out,
                          "\nFor uniform's error: the rays adaptive " + rule +
                              " needs (interpolated between its resolutions) / uniform's rays",
                          seeds);
        for (const std::string& plan : plans_of(runs)) {
            std::vector<std::optional<double>> ratios;
            for (const std::uint64_t s : seeds) {
                const Measured* m = find(runs, plan, s);
                if (m->plan.adaptive) {
                    break;
                }
                const std::optional<double> a = cost_for_error(envelope(runs, s, rule), m->error);
                ratios.push_back(a ? std::optional<double>(*a / static_cast<double>(m->spent.rays))
                                   : std::nullopt);
            }
            if (!ratios.empty()) {
                print_ratio_row(out, plan, ratios);
            }
        }
    }
}

void write_csv(std::ostream& out, const std::vector<Measured>& runs, double pixels) {
    out << "plan,nx,ny,adaptive,pixel_variance,ray_variance,probability,seed,rays_per_pixel,"
           "samples_per_pixel,eye_per_pixel,rms_error\n";
    for (const Measured& m : runs) {
        out << describe(m.plan) << ',' << m.plan.nx << ',' << m.plan.ny << ','
            << (m.plan.adaptive ? 1 : 0) << ',';
        if (m.plan.adaptive) {
            out << m.plan.pixel_variance << ',' << m.plan.ray_variance << ',' << m.plan.probability;
        } else {
            out << ",,";  // -Dx: no stop rule
        }
        out << ',' << m.seed << ',' << format("%.3f", static_cast<double>(m.spent.rays) / pixels)
            << ',' << format("%.3f", static_cast<double>(m.spent.samples) / pixels) << ','
            << format("%.4f", static_cast<double>(m.spent.eye) / pixels) << ','
            << format("%.4f", m.error) << '\n';
    }
}

}  // namespace rt::bench
