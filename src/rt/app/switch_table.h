// The command-line switches as data: one row per switch of the manual's Appendix, plus the long
// options. The parser, bare `rt`, `rt --help` and docs/switches.md are all rendered from it.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "rt/app/options.h"

namespace rt {

/// How a switch takes its argument. A short switch's argument may be attached ("-m2.0",
/// "-A40.0,1.0") or follow after a space ("-Wc 0.7", "-L 250"); a long option's follows after a
/// space ("--threads 2").
enum class ArgForm {
    None,     ///< "-Dd"
    Number,   ///< "-m2.0"
    Pair,     ///< two numbers and a comma: "-A40.0,1.0"
    Integer,  ///< "-L250", "--threads 2"
    Text,     ///< "--output FILE"
};

/// Switches of one group exclude one another (the manual's "only one -S switch").
enum class Exclusive { None, SpecularModel, HighlightColor, PhongShading, WarnLight };

/// The heading a switch is listed under in `rt --help` and docs/switches.md.
enum class Topic {
    Output,
    SpatialEncoding,
    Specular,
    Lights,
    Highlights,
    Disable,
    FileFormat,
    Illumination,
    AdaptiveSampling,
    OldVersions,
    Debugging,
    Program,
};

/// Whether this release does what the switch asks; NotYet switches are refused, never ignored.
enum class Status { Implemented, NotYet };

/// The values a switch's argument may take. Integers use the same bounds.
struct Range {
    double low = 0.0;
    double high = 0.0;
    bool low_open = false;   ///< low itself excluded
    bool high_open = false;  ///< high itself excluded
    bool bounded_above = false;

    bool contains(double value) const;
    /// "> 0", ">= 0", "in (0, 1)", "in (0, pi]", "from 1 to 20".
    std::string describe() const;
};

/// One number of a switch's argument: its name in the manual's words and its range.
struct Operand {
    std::string_view name;  ///< "m", "the multiplier"; empty when the switch takes no number
    Range range;
};

/// A switch's argument once read and checked; which members are set depends on the ArgForm.
struct SwitchArgument {
    double first = 0.0;        ///< Number, first of a Pair
    double second = 0.0;       ///< second of a Pair
    std::int64_t integer = 0;  ///< Integer
    std::string text;          ///< Text
};

struct SwitchSpec {
    std::string_view spelling;  ///< "-Stg", "--output"
    std::string_view alias;     ///< another accepted spelling ("-DI" for "-Dl"), or empty
    ArgForm form = ArgForm::None;
    Exclusive group = Exclusive::None;
    Topic topic = Topic::Output;
    Operand first;
    Operand second;
    bool repeatable = false;  ///< may be given more than once (--output)
    /// Sets the Options fields; captureless, so the table stays plain data.
    void (*apply)(Options&, const SwitchArgument&) = nullptr;
    std::string_view summary;  ///< the manual's one-line description
    std::string_view details;  ///< the Appendix's explanation, shortened
    std::string_view section;  ///< where the manual describes it: "App.", "2.2", "3.1"
    std::string_view example;  ///< an argument as a user types it: "-Stg1.0", "-Wc 0.7"
    Status status = Status::Implemented;
    std::string_view feature;  ///< what is missing when NotYet: "texture mapping"
    /// The library's name for the setting the switch sets, as its SettingErrors say it
    /// ("octree node limit"), or empty.
    std::string_view setting;
    /// Whether it decides the picture, so that a .gro records it for --resume; false for the
    /// options that only say where and how to run (--output, --threads, --quiet, ...).
    bool recorded = true;

    bool is_long_option() const { return spelling.starts_with("--"); }
};

/// Every switch, in the Appendix's order, then the long options.
std::span<const SwitchSpec> switch_table();

/// A SettingError's message with the switches that set each named setting put after its name:
/// "raise the octree node limit (-ol) or lower the octree depth (-od)".
std::string name_the_switches(const std::string& message);

/// The heading of a topic: "Specular reflection models (-S, one only)".
std::string_view topic_title(Topic topic);

/// The group's subject in conflict messages: "the specular model".
std::string_view exclusive_subject(Exclusive group);

}  // namespace rt
