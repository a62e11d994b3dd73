#include "fuzz_input.h"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <system_error>

#include <unistd.h>

namespace rt::fuzz {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view kFolderPrefix = "rt-fuzz-";

// The folders of fuzz processes that have ended: libFuzzer's fork mode ends its jobs with _Exit,
// which skips the atexit below, and a crash skips it too.
void remove_stale_folders() {
    std::error_code ec;
    for (const fs::directory_entry& entry : fs::directory_iterator(fs::temp_directory_path(), ec)) {
        const std::string name = entry.path().filename().string();
        if (!name.starts_with(kFolderPrefix)) {
            continue;
        }
        const std::string digits = name.substr(kFolderPrefix.size());
        if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos ||
            digits.size() > 9) {
            continue;
        }
        const pid_t pid = static_cast<pid_t>(std::stol(digits));
        if (::kill(pid, 0) != 0 && errno == ESRCH) {
            fs::remove_all(entry.path(), ec);
        }
    }
}

fs::path make_scratch_folder() {
    remove_stale_folders();
    fs::path folder =
        fs::temp_directory_path() / (std::string(kFolderPrefix) + std::to_string(::getpid()));
    fs::create_directories(folder);
    // A normal exit runs this; other ends leave the folder to the next run's clean-up.
    std::atexit([] {
        std::error_code ignored;
        fs::remove_all(scratch_folder(), ignored);
    });
    return folder;
}

}  // namespace

const fs::path& scratch_folder() {
    // Never destroyed: the clean-up at exit runs after static destructors would have run.
    static const fs::path* const folder = new fs::path(make_scratch_folder());
    return *folder;
}

fs::path write_scratch_file(std::string_view name, std::string_view bytes) {
    const fs::path path = scratch_folder() / fs::path(name);
    fs::create_directories(path.parent_path());
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) {
        finding("cannot write the fuzz input to " + path.string() + " (is /tmp full?)");
    }
    return path;
}

void clear_scratch_folder() {
    for (const fs::directory_entry& entry : fs::directory_iterator(scratch_folder())) {
        fs::remove_all(entry.path());
    }
}

ReaderDialect dialect_from_switches(std::string_view words) {
    ReaderDialect dialect;
    std::istringstream in{std::string(words)};
    std::string word;
    while (in >> word) {
        if (word == "-Df") {
            dialect.attributes_inline = true;
        } else if (word == "-Dp") {
            dialect.no_power_fields = true;
        } else if (word == "-Of") {
            dialect.attributes_inline = true;
            dialect.no_power_fields = true;
        } else if (word == "-Po" || word == "-Pt") {
            dialect.smooth_shade_field = true;
        } else if (word == "-M") {
            dialect.marks = true;
        } else if (word == "-R") {
            dialect.rgb_refraction = true;
        } else if (word == "-V") {
            dialect.textures = true;
        }
    }
    return dialect;
}

ReaderDialect dialect_of_input(std::string_view text) {
    constexpr std::string_view kSwitchLine = "# fuzz-switches:";
    if (text.substr(0, kSwitchLine.size()) != kSwitchLine) {
        return {};
    }
    const std::string_view line = text.substr(0, text.find('\n'));
    return dialect_from_switches(line.substr(kSwitchLine.size()));
}

GridSize grid_size_of(std::string_view text) {
    std::istringstream in{std::string(text)};
    std::string line;
    while (std::getline(in, line)) {
        line = line.substr(0, line.find('#'));
        if (line.find_first_not_of(" \t\r") == std::string::npos) {
            continue;
        }
        std::istringstream record(line);
        GridSize size;
        if (record >> size.rows >> size.columns && size.rows >= 1 && size.rows <= 1000 &&
            size.columns >= 1 && size.columns <= 1000) {
            return size;
        }
        return {};
    }
    return {};
}

SourceText scratch_source(std::string_view name, std::string_view bytes) {
    const fs::path path = write_scratch_file(name, bytes);
    return read_named_file(path, "fuzz input", std::string(name), SourceLocation{"fuzz", 1, 0});
}

void tell(const std::string& line) {
    static const bool verbose = std::getenv("RT_FUZZ_VERBOSE") != nullptr;
    if (verbose) {
        std::fprintf(stderr, "%s\n", line.c_str());
    }
}

void finding(const std::string& what) {
    std::fprintf(stderr, "rt fuzz finding: %s\n", what.c_str());
    std::fflush(stderr);
    std::abort();
}

void check_input_error(const InputError& error, Where where) {
    if (error.where().file.empty()) {
        finding("an InputError names no file: " + std::string(error.what()));
    }
    if (where == Where::FileAndLine && error.where().line < 1) {
        finding("an InputError names no line: " + std::string(error.what()));
    }
}

}  // namespace rt::fuzz
