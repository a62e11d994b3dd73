#include "rt/app/switch_parser.h"

#include <algorithm>
#include <limits>
#include <optional>
#include <string>

#include "rt/core/error.h"
#include "rt/core/text.h"

namespace rt {

namespace {

struct Match {
    const SwitchSpec* spec = nullptr;
    std::size_t length = 0;  ///< characters of the argument the spelling took
};

bool names(std::string_view spelling, std::string_view argument, bool whole) {
    if (spelling.empty()) {
        return false;
    }
    return whole ? argument == spelling : argument.starts_with(spelling);
}

// The parser chooses the longest spelling itself, so the table's order does not matter.
Match longest_match(std::string_view argument) {
    const bool is_long = argument.starts_with("--");
    const std::string_view name = is_long ? argument.substr(0, argument.find('=')) : argument;
    Match best;
    for (const SwitchSpec& spec : switch_table()) {
        for (const std::string_view spelling : {spec.spelling, spec.alias}) {
            if (names(spelling, name, is_long) && spelling.size() > best.length) {
                best = {&spec, spelling.size()};
            }
        }
    }
    return best;
}

std::string found(std::string_view text) {
    return text.empty() ? "nothing" : quote_token(text);
}

// "-S must be followed by p, g, tg or tb", for the switch families meaningless alone.
std::optional<std::string> family_rule(std::string_view argument) {
    if (argument.size() < 2 || argument.starts_with("--")) {
        return std::nullopt;
    }
    const std::string_view family = argument.substr(0, 2);
    std::vector<std::string_view> endings;
    for (const SwitchSpec& spec : switch_table()) {
        if (spec.spelling.size() > 2 && spec.spelling.starts_with(family)) {
            endings.push_back(spec.spelling.substr(2));
        }
    }
    if (endings.size() < 2) {
        return std::nullopt;
    }
    std::string rule = cat({family, " must be followed by "});
    for (std::size_t i = 0; i < endings.size(); ++i) {
        rule += i == 0 ? "" : i + 1 == endings.size() ? " or " : ", ";
        rule += endings[i];
    }
    return rule;
}

// A word no row takes. The family's rule helps only when no switch matched at all ("-Sx"); for
// a known switch with junk after it ("-Dpx") the word itself says enough.
[[noreturn]] void unknown_switch(std::string_view argument, bool matched_a_row) {
    const std::optional<std::string> rule = matched_a_row ? std::nullopt : family_rule(argument);
    if (rule && argument.size() == 2) {
        throw UsageError(*rule);
    }
    std::string message = cat({"unknown switch ", quote_token(argument)});
    if (rule) {
        message += cat({" (", *rule, ")"});
    }
    throw UsageError(message);
}

[[noreturn]] void expected(const SwitchSpec& spec, std::string_view what, std::string_view text) {
    std::string message = cat(
        {spec.spelling, ": expected ", what, " after ", spec.spelling, ", found ", found(text)});
    throw UsageError(message);
}

void check_range(const SwitchSpec& spec, const Operand& operand, double value,
                 std::string_view text) {
    if (!operand.range.contains(value)) {
        throw UsageError(cat({spec.spelling, ": ", operand.name, " must be ",
                              operand.range.describe(), ", found ", quote_token(text)}));
    }
}

double read_number(const SwitchSpec& spec, std::string_view text) {
    const std::optional<double> value = parse_double(text);
    if (!value) {
        expected(spec, "a number", text);
    }
    check_range(spec, spec.first, *value, text);
    return *value;
}

// Digits, after an optional sign: a whole number, however large.
bool written_as_whole_number(std::string_view text) {
    if (!text.empty() && (text.front() == '-' || text.front() == '+')) {
        text.remove_prefix(1);
    }
    return !text.empty() &&
           std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
}

std::int64_t read_integer(const SwitchSpec& spec, std::string_view text) {
    const std::optional<std::int64_t> value = parse_integer(text);
    if (!value && written_as_whole_number(text)) {
        // A whole number beyond 64 bits: its range, not its form, is what is wrong.
        const std::optional<double> approximately = parse_double(text);
        if (approximately) {
            check_range(spec, spec.first, *approximately, text);
        }
        const bool negative = text.front() == '-';
        throw UsageError(cat({spec.spelling, ": ", spec.first.name, " must be ",
                              negative ? "at least " : "at most ",
                              std::to_string(negative ? std::numeric_limits<std::int64_t>::min()
                                                      : std::numeric_limits<std::int64_t>::max()),
                              ", found ", quote_token(text)}));
    }
    if (!value) {
        expected(spec, "a whole number", text);
    }
    check_range(spec, spec.first, static_cast<double>(*value), text);
    return *value;
}

SwitchArgument read_pair(const SwitchSpec& spec, std::string_view text) {
    const std::size_t comma = text.find(',');
    const std::optional<double> first = parse_double(text.substr(0, comma));
    const std::optional<double> second =
        comma == std::string_view::npos ? std::nullopt : parse_double(text.substr(comma + 1));
    if (!first || !second) {
        expected(spec, "two numbers separated by a comma", text);
    }
    check_range(spec, spec.first, *first, text.substr(0, comma));
    check_range(spec, spec.second, *second, text.substr(comma + 1));
    SwitchArgument argument;
    argument.first = *first;
    argument.second = *second;
    return argument;
}

SwitchArgument read_text(const SwitchSpec& spec, std::string_view text) {
    // A value that looks like a switch is almost surely a forgotten value, not a file name (or
    // the I/N of --tile, the NAME of --accel: named as the help names them).
    if (text.empty() || text.starts_with("-")) {
        expected(spec, spec.first.name.starts_with("FILE") ? "a file name" : spec.first.name, text);
    }
    SwitchArgument argument;
    argument.text = std::string(text);
    return argument;
}

// The arguments left to read; a switch may take the next one as its value.
class ArgumentCursor {
public:
    explicit ArgumentCursor(const std::vector<std::string>& args) : args_(args) {}
    bool done() const { return next_ == args_.size(); }
    std::string_view take() { return args_[next_++]; }

private:
    const std::vector<std::string>& args_;
    std::size_t next_ = 0;
};

// Every argument may be attached ("-m2.0") or follow after a space ("-m 2.0", "-Wc 0.7").
bool takes_separate(ArgForm form) {
    return form != ArgForm::None;
}

SwitchArgument read_argument(const SwitchSpec& spec, std::string_view text) {
    SwitchArgument argument;
    switch (spec.form) {
        case ArgForm::None:
            break;
        case ArgForm::Number:
            argument.first = read_number(spec, text);
            break;
        case ArgForm::Pair:
            return read_pair(spec, text);
        case ArgForm::Integer:
            argument.integer = read_integer(spec, text);
            break;
        case ArgForm::Text:
            return read_text(spec, text);
    }
    return argument;
}

// What the parse has seen so far, to check duplicates and exclusive groups.
struct Seen {
    std::vector<const SwitchSpec*> switches;  ///< each row once, so at most the table's size
    const SwitchSpec* not_yet = nullptr;      ///< the first switch this release refuses
    std::vector<std::string> scenes;
};

void check_combination(const SwitchSpec& spec, const Seen& seen) {
    for (const SwitchSpec* earlier : seen.switches) {
        if (earlier == &spec && !spec.repeatable) {
            throw UsageError(cat({spec.spelling, " is given twice: give each switch once"}));
        }
        if (earlier->group == spec.group && spec.group != Exclusive::None && earlier != &spec) {
            const std::string pair = cat({earlier->spelling, " and ", spec.spelling});
            if (spec.group == Exclusive::PhongShading) {
                throw UsageError(cat({pair, " cannot be used together"}));
            }
            throw UsageError(cat({pair, " both choose ", exclusive_subject(spec.group),
                                  ": give only one ", spec.spelling.substr(0, 2), " switch"}));
        }
    }
}

// One switch, with the argument after it when its form takes one there.
void parse_switch(std::string_view word, ArgumentCursor& cursor, Options& options, Seen& seen) {
    const Match match = longest_match(word);
    if (match.spec == nullptr) {
        unknown_switch(word, false);
    }
    const SwitchSpec& spec = *match.spec;
    // Whatever follows the spelling: "2.0" of "-m2.0", "=a.png" of "--output=a.png" (a long
    // option matches only up to its '=').
    std::string_view text = word.substr(match.length);
    const bool glued = !text.empty();
    if (spec.is_long_option() && glued) {
        text.remove_prefix(1);
    }
    if (spec.form == ArgForm::None && glued) {
        if (spec.is_long_option()) {
            throw UsageError(cat({spec.spelling, " takes no value"}));
        }
        unknown_switch(word, true);
    }
    std::string verbatim(word);
    std::vector<std::string> words{std::string(word)};
    if (!glued && takes_separate(spec.form) && !cursor.done()) {
        text = cursor.take();
        verbatim += cat({" ", text});
        words.emplace_back(text);
    }
    const SwitchArgument argument = read_argument(spec, text);
    check_combination(spec, seen);
    spec.apply(options, argument);
    if (std::find(seen.switches.begin(), seen.switches.end(), &spec) == seen.switches.end()) {
        seen.switches.push_back(&spec);
    }
    if (!spec.is_long_option()) {
        options.given_switches.push_back(verbatim);
    }
    if (spec.recorded) {
        options.render_arguments.push_back(std::move(words));
    }
    if (spec.status == Status::NotYet && seen.not_yet == nullptr) {
        seen.not_yet = &spec;
    }
}

// --tile writes its part file and nothing else: the images come from merge.
void check_tile(const Options& options) {
    if (!options.tile) {
        return;
    }
    if (options.no_gro) {
        throw UsageError("--tile writes a part file, which -n would leave out: drop -n");
    }
    if (!options.outputs.empty()) {
        throw UsageError(
            "--tile writes only its part file: merge writes the images (merge PARTS... "
            "--output FILE)");
    }
}

void check_complete(const Options& options, const Seen& seen) {
    check_tile(options);
    if (options.early == EarlyVersion::OldVersion && options.given_switches.size() > 1) {
        throw UsageError("-O1 must be used alone, without other switches");
    }
    if (!options.resume.empty() && seen.scenes.empty() && options.model.empty()) {
        return;  // the .gro names the scene
    }
    if (!options.model.empty()) {
        if (!seen.scenes.empty()) {
            throw UsageError(
                cat({"--model renders a model without a scene, but ", quote_token(seen.scenes[0]),
                     " is given too: give a scene or --model FILE"}));
        }
        return;
    }
    if (seen.scenes.empty()) {
        throw UsageError(
            "no scene given: the command is rt SCENE [switches] or rt --model FILE "
            "[switches]");
    }
    if (seen.scenes.size() > 1) {
        throw UsageError(cat({"two scenes given, ", quote_token(seen.scenes[0]), " and ",
                              quote_token(seen.scenes[1]), ": give exactly one scene"}));
    }
    if (seen.scenes[0].empty()) {
        throw UsageError("expected a scene name, found ''");
    }
}

bool contains(const std::vector<std::string>& args, std::string_view word) {
    return std::find(args.begin(), args.end(), word) != args.end();
}

}  // namespace

const SwitchSpec* match_switch(std::string_view argument) {
    return longest_match(argument).spec;
}

Options parse_command_line(const std::vector<std::string>& args) {
    Options options;
    // Bare `rt`, --help and --version answer at once, whatever else is on the line.
    if (args.empty()) {
        options.show_usage = true;
        return options;
    }
    if (contains(args, "--help") || contains(args, "--version")) {
        options.show_help = contains(args, "--help");
        options.show_version = !options.show_help;
        return options;
    }
    Seen seen;
    ArgumentCursor cursor(args);
    while (!cursor.done()) {
        const std::string_view word = cursor.take();
        if (word.starts_with("-")) {
            parse_switch(word, cursor, options, seen);
        } else {
            seen.scenes.emplace_back(word);
        }
    }
    check_complete(options, seen);
    options.scene = seen.scenes.empty() ? std::string() : seen.scenes[0];
    if (!options.scene.empty()) {
        options.render_arguments.insert(options.render_arguments.begin(), {options.scene});
    }
    if (seen.not_yet != nullptr) {
        throw NotImplementedError(
            cat({seen.not_yet->spelling, ": ", seen.not_yet->feature, " is not implemented yet"}));
    }
    return options;
}

}  // namespace rt
