#include "study_arguments.h"

#include <charconv>
#include <string_view>

#include "rt/core/text.h"

#include "command_line/command_line.h"

namespace rt::bench {

namespace {

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
T number(const std::string& text, const std::string& option) {
    T value{};
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc{} || end != text.data() + text.size() || !(value > T{})) {
        throw CLI::ValidationError(option,
                                   "expected a positive number, found " + quote_token(text));
    }
    return value;
}

// "NxM" (or "N" for N x N).
SamplingPlan resolution(const std::string& text, bool adaptive, const std::string& option) {
    const std::vector<std::string> sides = split(text, 'x');
    if (sides.size() > 2) {
        throw CLI::ValidationError(option,
                                   "expected a sample resolution NxM, found " + quote_token(text));
    }
    SamplingPlan plan;
    plan.nx = number<int>(sides[0], option);
    plan.ny = sides.size() == 2 ? number<int>(sides[1], option) : plan.nx;
    plan.adaptive = adaptive;
    return plan;
}

// "NxM@var", "NxM@pvar/rvar" or either followed by ":prob": -Xp prob,pvar and -Xr prob,rvar.
SamplingPlan adaptive_plan(const std::string& text) {
    const std::string option = "--adaptive";
    const std::vector<std::string> parts = split(text, '@');
    SamplingPlan plan = resolution(parts[0], true, option);
    if (parts.size() > 2) {
        throw CLI::ValidationError(option, "expected NxM@var, found " + quote_token(text));
    }
    if (parts.size() == 2) {
        const std::vector<std::string> rule = split(parts[1], ':');
        const std::vector<std::string> variances = split(rule[0], '/');
        if (rule.size() > 2 || variances.size() > 2) {
            throw CLI::ValidationError(option,
                                       "expected NxM@pvar/rvar:prob, found " + quote_token(text));
        }
        plan.pixel_variance = number<double>(variances[0], option);
        plan.ray_variance =
            variances.size() == 2 ? number<double>(variances[1], option) : plan.pixel_variance;
        if (rule.size() == 2) {
            plan.probability = number<double>(rule[1], option);
        }
    }
    return plan;
}

PixelRect window(const std::string& text) {
    const std::string option = "--window";
    const std::vector<std::string> v = split(text, ',');
    std::vector<int> sides;
    for (const std::string& side : v) {
        if (const std::optional<std::int64_t> n = parse_integer(side)) {
            sides.push_back(static_cast<int>(*n));
        }
    }
    if (sides.size() != 4 || v.size() != 4) {
        throw CLI::ValidationError(option,
                                   "expected left,top,right,bottom, found " + quote_token(text));
    }
    const PixelRect w{sides[0], sides[1], sides[2], sides[3]};
    if (w.width() < 1 || w.height() < 1) {
        throw CLI::ValidationError(option, "empty window " + quote_token(text));
    }
    return w;
}

}  // namespace

void add_study_options(CLI::App& app, StudyArguments& out) {
    // rt's switches pass through; only --help is ours, so that no -h... of rt's is taken for it.
    app.allow_extras();
    app.set_help_flag("--help", "Print this help message and exit");
    app.add_option("--seeds", out.seeds, "seeds 1..N for every plan (default 6)")
        ->type_name("N")
        ->transform(cli::whole_number_at_least(1));
    app.add_option_function<std::string>(
           "--reference",
           [&out](const std::string& text) {
               out.reference = resolution(text, false, "--reference");
           },
           "the reference's sample resolution, -Dx (default 8x8)")
        ->type_name("NxM");
    app.add_option("--reference-renders", out.reference_renders,
                   "renders averaged for the reference, seeds 1001..; at least 2, to\n"
                   "know the reference's own noise (default 4)")
        ->type_name("M")
        ->transform(cli::whole_number_at_least(2));
    app.add_option_function<std::string>(
           "--window", [&out](const std::string& text) { out.window = window(text); },
           "the pixels to render (default: the scene's window)")
        ->type_name("l,t,r,b");
    app.add_option_function<std::vector<std::string>>(
           "--uniform",
           [&out](const std::vector<std::string>& texts) {
               for (const std::string& text : texts) {
                   out.uniform.push_back(resolution(text, false, "--uniform"));
               }
           },
           "-Dx plans NxM,... (default 2x2 to 6x6); repeats add up")
        ->type_name("LIST")
        ->delimiter(',')
        ->allow_extra_args(false);
    app.add_option_function<std::vector<std::string>>(
           "--adaptive",
           [&out](const std::vector<std::string>& texts) {
               for (const std::string& text : texts) {
                   out.adaptive.push_back(adaptive_plan(text));
               }
           },
           "adaptive plans NxM@var,... with -Xp and -Xr var (prob 0.2), or\n"
           "NxM@pvar/rvar:prob (default 4x4 at var 0.8 to 0.025); repeats add up")
        ->type_name("LIST")
        ->delimiter(',')
        ->allow_extra_args(false);
    app.add_option("--csv", out.csv, "one row per plan and seed")->type_name("FILE");
}

}  // namespace rt::bench
