// What rt's small programs (show, gen_switch_docs and the programs in bench/) share on top of
// CLI11: rt's exit code for a bad command line, one way to report it, and validators whose
// messages say what was expected. rt itself reads the manual's glued switches ("-Stb1.0",
// "-A40.0,1.0") with its own table (src/rt/app/switch_table.h); these programs have ordinary
// options, which a maintained parser reads better than hand-written loops.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include <CLI/CLI.hpp>

namespace rt::cli {

/// rt's exit codes: 0 ok, 1 bad input file, 2 usage, 3 I/O, 4 internal.
constexpr int kOkExit = 0;
constexpr int kBadInputExit = 1;
constexpr int kUsageExit = 2;
constexpr int kIoExit = 3;
constexpr int kInternalExit = 4;

/// Runs body and returns its exit code; an rt::Error it throws is printed as "PROGRAM: message"
/// and becomes its exit code (any other exception: "internal error", 4). `usage_hint`, if given,
/// follows a usage error on a line of its own.
int exit_code_of(std::string_view program, const std::function<int()>& body,
                 std::string_view usage_hint = {});

/// What a command line without any argument asks for.
enum class BareCommand { Runs, PrintsHelp };

/// Settings every program's App shares: a repeated option's last value wins, and the help's
/// columns are wide enough for our names. `usage`, if given, replaces the help's generated
/// "Usage: PROGRAM [OPTIONS] ..." tail, for programs that pass arguments on to rt.
void configure(CLI::App& app, std::string usage = {});

/// Parses argv into app. Returns the exit code if the program should stop: 0 after printing the
/// help (--help, or no arguments when `bare` says so), kUsageExit after printing a usage error
/// as "PROGRAM: message" and a pointer to --help; nothing if the program should go on.
std::optional<int> parse(CLI::App& app, int argc, const char* const* argv, BareCommand bare);

/// A number as rt reads numbers (decimal, the whole text) of at least `least`.
CLI::Validator number_at_least(double least);

/// A number as rt reads numbers, above `bound`.
CLI::Validator number_above(double bound);

/// A decimal whole number of at least `least`. CLI11 alone would read "010" as octal and "0x10"
/// as hex; this rewrites the text as plain decimal first.
CLI::Validator whole_number_at_least(long long least);

}  // namespace rt::cli
