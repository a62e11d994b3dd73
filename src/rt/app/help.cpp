#include "rt/app/help.h"

#include <algorithm>
#include <array>
#include <string_view>

#include "rt/app/version.h"
#include "rt/core/text.h"

namespace rt {

namespace {

constexpr std::string_view kNotYet = "not implemented yet";
constexpr std::size_t kHelpWidth = 96;

// The rules of the command line, said once for --help and docs/switches.md.
constexpr std::array<std::string_view, 7> kRules = {
    "SCENE is the one argument not starting with '-': the file SCENE.scn, or SCENE as given. The "
    "picture goes to SCENE.gro in the current folder. With --model FILE in its place, rt renders "
    "a model file without a scene, to FILE's stem with .gro.",
    "Switches come in any order. The longest spelling wins: -dsp is not -ds followed by p.",
    "A switch's argument may be attached (-m2.0, -A40.0,1.0, -L250) or follow after a space "
    "(-m 2.0, -Wc 0.7, -L 250).",
    "Each switch may be given once (only --output repeats). -S, -C, -P and -W choose one thing "
    "each: give at most one switch of each. -O1 must be used alone.",
    "-Po or -Pt must be given if and only if the .scn has the smooth-shading field, -M if and "
    "only if it has a $@shapes line, -V if and only if it has texture-mapped surfaces.",
    "A switch marked 'not implemented yet' is recognised, its argument checked, and then the run "
    "stops with that message rather than render something else.",
    "The manual's misprint -DI is accepted for -Dl.",
};

constexpr std::array kTopics = {
    Topic::Output,           Topic::SpatialEncoding, Topic::Specular,   Topic::Lights,
    Topic::Highlights,       Topic::Disable,         Topic::FileFormat, Topic::Illumination,
    Topic::AdaptiveSampling, Topic::OldVersions,     Topic::Debugging,  Topic::Program,
};

// "the multiplier" is "multiplier" in a synopsis or a range; "FILE" and "N" stay as they are.
std::string_view bare_name(const Operand& operand) {
    const std::string_view name = operand.name;
    return name.starts_with("the ") ? name.substr(4) : name;
}

std::string placeholder(const Operand& operand) {
    return cat({"<", bare_name(operand), ">"});
}

std::string operand_text(const Operand& operand) {
    return cat({bare_name(operand), " ", operand.range.describe()});
}

std::string padded(std::string text, std::size_t width) {
    if (text.size() < width) {
        text.append(width - text.size(), ' ');
    }
    return text;
}

// One switch in `rt --help`: synopsis and summary, then its argument and example.
std::string help_entry(const SwitchSpec& spec) {
    constexpr std::size_t kColumn = 26;
    std::string left = cat({"  ", synopsis(spec)});
    if (!spec.alias.empty()) {
        left += cat({" (or ", spec.alias, ")"});
    }
    std::string text = left.size() < kColumn ? padded(left, kColumn)
                                             : cat({left, "\n", std::string(kColumn, ' ')});
    text += spec.summary;
    if (spec.status == Status::NotYet) {
        const std::string mark = cat({"(", kNotYet, ")"});
        const bool fits = kColumn + spec.summary.size() + 1 + mark.size() <= kHelpWidth;
        text += fits ? cat({" ", mark}) : cat({"\n", std::string(kColumn + 2, ' '), mark});
    }
    text += "\n";
    const std::string argument = argument_text(spec);
    if (!argument.empty()) {
        text += cat({std::string(kColumn + 2, ' '), argument, "; e.g. ", spec.example, "\n"});
    }
    return text;
}

std::string escape_cell(std::string_view text) {
    std::string cell;
    for (const char c : text) {
        if (c == '|') {
            cell += '\\';
        }
        cell += c;
    }
    return cell;
}

std::string markdown_row(const SwitchSpec& spec) {
    std::string names = cat({"`", synopsis(spec), "`"});
    if (!spec.alias.empty()) {
        names += cat({" (or `", spec.alias, "`)"});
    }
    std::string meaning = cat({"*", escape_cell(spec.summary), "*"});
    if (!spec.details.empty()) {
        meaning += cat({" — ", escape_cell(spec.details)});
    }
    const std::string status = spec.status == Status::Implemented
                                   ? std::string("implemented")
                                   : cat({kNotYet, ": ", spec.feature});
    return cat({"| ", names, " | `", spec.example, "` | ", escape_cell(argument_text(spec)), " | ",
                meaning, " | ", spec.section, " | ", status, " |\n"});
}

std::string markdown_topic(Topic topic) {
    std::string text = cat({"\n## ", topic_title(topic), "\n\n"});
    text += "| Switch | Example | Argument | Meaning | Manual | Status |\n";
    text += "|---|---|---|---|---|---|\n";
    for (const SwitchSpec& spec : switch_table()) {
        if (spec.topic == topic) {
            text += markdown_row(spec);
        }
    }
    return text;
}

bool some_switch_not_yet() {
    return std::any_of(switch_table().begin(), switch_table().end(),
                       [](const SwitchSpec& spec) { return spec.status == Status::NotYet; });
}

// The rules as a list; wrapped for a terminal when width > 0, one line each for Markdown. The
// rule about unfinished switches is said only while there is one.
std::string rules_list(std::size_t width) {
    std::string text;
    for (const std::string_view rule : kRules) {
        if (rule.find(kNotYet) != std::string_view::npos && !some_switch_not_yet()) {
            continue;
        }
        std::string line = "-";
        std::size_t start = 0;
        while (start < rule.size()) {
            const std::size_t space = rule.find(' ', start);
            const std::string_view word = rule.substr(start, space - start);
            if (width > 0 && line.size() + 1 + word.size() > width) {
                text += cat({line, "\n"});
                line.assign(1, ' ');  // not = " ": that trips a GCC 12 -Wrestrict false alarm
            }
            line += cat({" ", word});
            start = space == std::string_view::npos ? rule.size() : space + 1;
        }
        text += cat({line, "\n"});
    }
    return text;
}

}  // namespace

std::string synopsis(const SwitchSpec& spec) {
    std::string text(spec.spelling);
    if (spec.form == ArgForm::None) {
        return text;
    }
    if (spec.is_long_option()) {
        return cat({text, " ", spec.first.name});  // "--threads N", "--output FILE"
    }
    // Written as the example is: "-m<multiplier>", but "-Wc <angle>".
    text += spec.example.find(' ') == std::string_view::npos ? "" : " ";
    text += placeholder(spec.first);
    if (spec.form == ArgForm::Pair) {
        text += cat({",", placeholder(spec.second)});
    }
    return text;
}

std::string argument_text(const SwitchSpec& spec) {
    if (spec.form == ArgForm::None || spec.form == ArgForm::Text) {
        return "";
    }
    if (spec.is_long_option()) {
        return operand_text(spec.first);
    }
    std::string text = operand_text(spec.first);
    if (spec.form == ArgForm::Pair) {
        text += cat({", ", operand_text(spec.second)});
    }
    return cat({text, ", attached or separate"});
}

std::string usage_text() {
    std::string text =
        "usage: rt SCENE [switches]   (SCENE.scn or SCENE; 'rt --help' explains every switch)\n";
    for (const SwitchSpec& spec : switch_table()) {
        if (!spec.is_long_option()) {
            const std::string_view mark = spec.status == Status::NotYet ? "* " : "  ";
            text += cat({"  ", padded(std::string(spec.example), 14), mark, spec.summary, "\n"});
        }
    }
    if (some_switch_not_yet()) {
        text += cat({"* ", kNotYet, "\n"});
    }
    text +=
        "also: --output FILE (repeatable), --model FILE, --seed N, --threads N, --quiet, --help, "
        "--version\n";
    return text;
}

std::string help_text() {
    std::string text =
        "Usage: rt SCENE [switches]\n       rt --model FILE [switches]\n       rt --help | "
        "--version\n\n";
    text += "Ray traces a scene of the CMU RayTracer 6.0 (CMU-RI-TR-88-18, 1988).\n\n";
    text += rules_list(kHelpWidth);
    for (const Topic topic : kTopics) {
        text += cat({"\n", topic_title(topic), ":\n"});
        for (const SwitchSpec& spec : switch_table()) {
            if (spec.topic == topic) {
                text += help_entry(spec);
            }
        }
    }
    return text;
}

std::string switches_markdown() {
    std::string text = "# Command-line switches\n\n";
    text +=
        "<!-- Generated from src/rt/app/switch_table.cpp: do not edit; regenerate with\n"
        "     build/bin/gen_switch_docs docs/switches.md -->\n\n";
    text +=
        "`rt SCENE [switches]` or `rt --model FILE [switches]`. The switches are those of the "
        "manual's Appendix (with the "
        "manual's section for each), plus a few long options new in this version. Bare `rt` "
        "prints the brief list, `rt --help` the whole list.\n\n";
    text += rules_list(0);
    for (const Topic topic : kTopics) {
        text += markdown_topic(topic);
    }
    return text;
}

std::string version_text() {
    return cat({"rt ", kVersion, " (CMU RayTracer 6.0 reimplementation)"});
}

}  // namespace rt
