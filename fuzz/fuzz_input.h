// What every fuzz target shares: the scratch folder its inputs are written into (the readers take
// paths), the reader switches an input may ask for, and the rule that a reader answers with a
// value or an rt::InputError naming its file, and nothing else (fuzz/README.md).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "rt/core/error.h"
#include "rt/scene/read/dialect.h"
#include "rt/scene/read/source_text.h"

namespace rt::fuzz {

inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
    return {reinterpret_cast<const char*>(data), size};
}

/// This process's folder for fuzz inputs, made on first use and removed when the process ends.
const std::filesystem::path& scratch_folder();

/// Writes `bytes` to scratch_folder() / name (replacing it) and returns its path. `name` may hold
/// folders ("models/box.obj"); they are made.
std::filesystem::path write_scratch_file(std::string_view name, std::string_view bytes);

/// Removes everything in the scratch folder (the files of the previous input).
void clear_scratch_folder();

/// The reader switches among `words` (-Df -Dp -Of -Po -Pt -M -R -V); other words are ignored.
ReaderDialect dialect_from_switches(std::string_view words);

/// The reader switches a first line "# fuzz-switches: -M -V" asks for (none without that line).
/// The line is a comment to the readers that take it: they count only $ lines.
ReaderDialect dialect_of_input(std::string_view text);

/// The input written to the scratch folder as `name` and read back as the program reads a file
/// the .scn names (read_named_file): binary junk is an InputError before any reader sees it.
SourceText scratch_source(std::string_view name, std::string_view bytes);

/// The rows and columns of cells a -V grid file or texture map names in its first record
/// ("ROWS COLUMNS"), each 1 to 1000, for the .scn line the reader checks them against; 1 x 1 when
/// the first record is not two such numbers.
struct GridSize {
    std::int64_t rows = 1;
    std::int64_t columns = 1;
};
GridSize grid_size_of(std::string_view text);

/// Prints the line to stderr when the environment sets RT_FUZZ_VERBOSE (to see what a replayed
/// input does).
void tell(const std::string& line);

/// Prints "rt fuzz finding: <what>" and aborts, so that libFuzzer keeps the input.
[[noreturn]] void finding(const std::string& what);

/// How strictly an InputError must say where the fault is.
enum class Where { FileAndLine, File };

/// Checks an InputError: its message must name the file, and with FileAndLine a line too
/// (model files and the .gro pixel block have no lines to name).
void check_input_error(const InputError& error, Where where);

/// Runs `read` (a reader applied to the input): a value or an InputError is an answer; any other
/// exception propagates, and libFuzzer reports it as a crash.
template <typename Read>
void expect_value_or_input_error(Read&& read, Where where = Where::FileAndLine) {
    try {
        (void)read();
    } catch (const InputError& error) {
        check_input_error(error, where);
    }
}

}  // namespace rt::fuzz
