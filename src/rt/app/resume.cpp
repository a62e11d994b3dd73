#include "rt/app/resume.h"

#include <algorithm>

#include "rt/app/switch_parser.h"
#include "rt/app/version.h"
#include "rt/core/error.h"
#include "rt/image/gro_format.h"
#include "rt/image/picture_parts.h"

#include <fmt/format.h>

namespace rt {

namespace {

// Units as the user typed them, in a fixed order, so that the same switches in another order
// compare equal.
std::vector<std::string> sorted_units(const std::vector<std::vector<std::string>>& arguments) {
    std::vector<std::string> units;
    for (const std::vector<std::string>& words : arguments) {
        std::string unit;
        for (const std::string& word : words) {
            unit += (unit.empty() ? "" : " ") + word;
        }
        units.push_back(unit);
    }
    std::sort(units.begin(), units.end());
    return units;
}

std::string joined(const std::vector<std::vector<std::string>>& arguments) {
    std::string text;
    for (const std::vector<std::string>& words : arguments) {
        for (const std::string& word : words) {
            text += (text.empty() ? "" : " ") + word;
        }
    }
    return text;
}

}  // namespace

std::string encode_arguments(const std::vector<std::vector<std::string>>& arguments) {
    std::string text;
    for (const std::vector<std::string>& words : arguments) {
        for (const std::string& word : words) {
            if (!text.empty()) {
                text += ' ';
            }
            for (const char c : word) {
                text += c == ' ' ? "\\s" : c == '\\' ? "\\\\" : std::string(1, c);
            }
        }
    }
    return text;
}

std::vector<std::string> decode_arguments(std::string_view text) {
    std::vector<std::string> words(1);
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] == ' ') {
            words.emplace_back();
        } else if (text[i] == '\\' && i + 1 < text.size()) {
            ++i;
            words.back() += text[i] == 's' ? ' ' : text[i];
        } else {
            words.back() += text[i];
        }
    }
    return words;
}

ResumePlan plan_resume(const Options& given) {
    const std::string& file = given.resume;
    ResumePlan plan{{}, read_gro(file)};
    const FilmProvenance& p = plan.done.provenance;
    if (p.arguments.empty()) {
        throw UsageError(
            fmt::format("--resume: {} does not record what rendered it (it was written by an "
                        "older rt, or by -w): it cannot be resumed; render the scene again",
                        file));
    }
    if (plan.done.complete()) {
        throw UsageError(fmt::format("--resume: {} is complete: there is nothing to resume", file));
    }
    const std::string program = "rt " + std::string(kVersion);
    if (p.program != program) {
        throw UsageError(fmt::format(
            "--resume: {} was rendered by {}, this is {}: the rest of its rows could differ; "
            "render the scene again",
            file, p.program, program));
    }
    plan.options = parse_command_line(decode_arguments(p.arguments));
    // Given a scene or switches, they must be the recorded ones (in any order).
    if (!given.render_arguments.empty() &&
        sorted_units(given.render_arguments) != sorted_units(plan.options.render_arguments)) {
        throw UsageError(fmt::format(
            "--resume: {} was rendered with '{}', but this command gives '{}': give the same "
            "scene and switches, or none (the recorded ones are used)",
            file, joined(plan.options.render_arguments), joined(given.render_arguments)));
    }
    if (std::to_string(plan.options.shading.sampling.seed) != p.seed) {
        throw UsageError(
            fmt::format("--resume: {} was rendered with seed {}, but its switches now give seed {}",
                        file, p.seed, plan.options.shading.sampling.seed));
    }
    Options& o = plan.options;
    if (!plan.done.part.part.empty()) {
        // A part file (--tile) is resumed as the same part; its header line says which.
        o.tile = parse_part_line(plan.done.part.part);
        if (!o.tile) {
            throw UsageError(fmt::format("--resume: {} has an unreadable part line '{}'", file,
                                         plan.done.part.part));
        }
    }
    o.outputs = given.outputs;
    o.threads = given.threads;
    o.quiet = given.quiet;
    o.no_window = given.no_window;
    o.resume = given.resume;
    return plan;
}

void check_resumable(const Film& done, const std::string& inputs, int view_width, int view_height,
                     const PixelRect& window) {
    if (done.provenance.inputs != inputs) {
        throw UsageError(fmt::format(
            "--resume: the scene's files have changed since the render began (their digest was "
            "{}, it is now {}): the rows would not match; render the scene again",
            done.provenance.inputs, inputs));
    }
    const PixelRect& a = done.window();
    const PixelRect& b = window;
    if (done.view_width() != view_width || done.view_height() != view_height || a.left != b.left ||
        a.top != b.top || a.right != b.right || a.bottom != b.bottom) {
        throw UsageError(
            "--resume: the scene's view or window differs from the interrupted picture's");
    }
}

}  // namespace rt
