#include "study_arguments.h"

#include <charconv>
#include <string_view>

#include "rt/core/error.h"

namespace rt::bench {

namespace {

std::optional<std::string> take_value(const std::vector<std::string>& args, std::size_t& i,
                                      std::string_view name) {
    const std::string& arg = args[i];
    if (arg == name) {
        if (i + 1 >= args.size()) {
            throw UsageError(std::string(name) + ": a value must follow");
        }
        return args[++i];
    }
    if (arg.size() > name.size() && arg.compare(0, name.size(), name) == 0 &&
        arg[name.size()] == '=') {
        return arg.substr(name.size() + 1);
    }
    return std::nullopt;
}

std::vector<std::string> split(const std::string& text, char separator) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    while (true) {
        const std::size_t end = text.find(separator, start);
        parts.push_back(text.substr(start, end - start));
        if (end == std::string::npos) {
            return parts;
        }
        start = end + 1;
    }
}

template <typename T>
T number(const std::string& text, std::string_view what) {
    T value{};
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc{} || end != text.data() + text.size() || !(value > T{})) {
        throw UsageError(std::string(what) + ": expected a positive number, found '" + text + "'");
    }
    return value;
}

// "NxM" (or "N" for N x N).
SamplingPlan resolution(const std::string& text, bool adaptive) {
    const std::vector<std::string> sides = split(text, 'x');
    if (sides.size() > 2) {
        throw UsageError("expected a sample resolution NxM, found '" + text + "'");
    }
    SamplingPlan plan;
    plan.nx = number<int>(sides[0], "sample resolution");
    plan.ny = sides.size() == 2 ? number<int>(sides[1], "sample resolution") : plan.nx;
    plan.adaptive = adaptive;
    return plan;
}

// "NxM@var", "NxM@pvar/rvar" or either followed by ":prob": -Xp prob,pvar and -Xr prob,rvar.
SamplingPlan adaptive_plan(const std::string& text) {
    const std::vector<std::string> parts = split(text, '@');
    SamplingPlan plan = resolution(parts[0], true);
    if (parts.size() > 2) {
        throw UsageError("--adaptive: expected NxM@var, found '" + text + "'");
    }
    if (parts.size() == 2) {
        const std::vector<std::string> rule = split(parts[1], ':');
        const std::vector<std::string> variances = split(rule[0], '/');
        if (rule.size() > 2 || variances.size() > 2) {
            throw UsageError("--adaptive: expected NxM@pvar/rvar:prob, found '" + text + "'");
        }
        plan.pixel_variance = number<double>(variances[0], "--adaptive");
        plan.ray_variance = variances.size() == 2 ? number<double>(variances[1], "--adaptive")
                                                  : plan.pixel_variance;
        if (rule.size() == 2) {
            plan.probability = number<double>(rule[1], "--adaptive");
        }
    }
    return plan;
}

PixelRect window(const std::string& text) {
    const std::vector<std::string> v = split(text, ',');
    if (v.size() != 4) {
        throw UsageError("--window: expected left,top,right,bottom, found '" + text + "'");
    }
    const PixelRect w{std::stoi(v[0]), std::stoi(v[1]), std::stoi(v[2]), std::stoi(v[3])};
    if (w.width() < 1 || w.height() < 1) {
        throw UsageError("--window: empty window '" + text + "'");
    }
    return w;
}

}  // namespace

StudyArguments parse_study_arguments(const std::vector<std::string>& args) {
    StudyArguments out;
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (const auto seeds = take_value(args, i, "--seeds")) {
            out.seeds = number<int>(*seeds, "--seeds");
        } else if (const auto reference = take_value(args, i, "--reference")) {
            out.reference = resolution(*reference, false);
        } else if (const auto renders = take_value(args, i, "--reference-renders")) {
            out.reference_renders = number<int>(*renders, "--reference-renders");
        } else if (const auto w = take_value(args, i, "--window")) {
            out.window = window(*w);
        } else if (const auto uniform = take_value(args, i, "--uniform")) {
            for (const std::string& part : split(*uniform, ',')) {
                out.uniform.push_back(resolution(part, false));
            }
        } else if (const auto adaptive = take_value(args, i, "--adaptive")) {
            for (const std::string& part : split(*adaptive, ',')) {
                out.adaptive.push_back(adaptive_plan(part));
            }
        } else if (const auto csv = take_value(args, i, "--csv")) {
            out.csv = *csv;
        } else {
            out.rt_args.push_back(args[i]);
        }
    }
    if (out.reference_renders < 2) {
        throw UsageError("--reference-renders: at least 2, to know the reference's own noise");
    }
    return out;
}

std::string study_usage() {
    return "usage: rt_adaptive_study [--seeds N] [--reference NxM] [--reference-renders M]\n"
           "         [--window l,t,r,b] [--uniform NxM,...] [--adaptive NxM@var,...]\n"
           "         [--csv FILE] SCENE [rt switches]\n"
           "  Renders SCENE's window through the library with every plan and seeds 1..N: -Dx at\n"
           "  each --uniform sample resolution, adaptive at each --adaptive resolution with -Xp\n"
           "  and -Xr var (prob 0.2). Each picture's RMS error (display levels) is measured\n"
           "  against the mean of M -Dx renders at the --reference resolution (seeds 1001..),\n"
           "  less that mean's own noise. Prints each plan's rays and error, adaptive's error\n"
           "  against uniform's at equal rays, and the rays each needs for the same error.\n";
}

}  // namespace rt::bench
