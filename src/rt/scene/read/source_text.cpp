#include "rt/scene/read/source_text.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <memory>
#include <system_error>

#include "rt/scene/read/reader_limits.h"

#include <fmt/format.h>

namespace rt {

namespace {

struct FileCloser {
    void operator()(std::FILE* f) const { std::fclose(f); }
};

std::string errno_reason(int error) {
    return std::error_code(error, std::generic_category()).message();
}

using OpenFile = std::unique_ptr<std::FILE, FileCloser>;

// The file opened for reading, or null with why not ("No such file or directory").
OpenFile open_for_reading(const std::filesystem::path& path, std::string& reason) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) {
        reason = errno_reason(EISDIR);
        return nullptr;
    }
    // A device such as /dev/zero or /dev/random would be read up to the size cap (a GiB) before
    // being refused; pipes stay allowed (a scene may come from a shell's process substitution).
    if (std::filesystem::is_character_file(path, ec) || std::filesystem::is_block_file(path, ec)) {
        reason = "a device, not a file";
        return nullptr;
    }
    OpenFile file(std::fopen(path.c_str(), "rb"));
    if (!file) {
        reason = errno_reason(errno);
    }
    return file;
}

bool is_forbidden_control(unsigned char c) {
    const bool blank = c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
    return (c < 0x20 && !blank) || c == 0x7f;
}

// Reads the bytes, or returns why not. Reading stops after the first block holding a byte no
// text file has (a Ctrl-Z apart, allowed at the very end): check_is_text reports it, and a big
// binary file is not read whole first.
bool read_bytes(const std::filesystem::path& path, std::string& bytes, std::string& reason) {
    const OpenFile file = open_for_reading(path, reason);
    if (!file) {
        return false;
    }
    // Read in blocks rather than trusting a size: pipes and special files have none.
    char block[1 << 16];
    std::size_t got = 0;
    while ((got = std::fread(block, 1, sizeof block, file.get())) > 0) {
        if (bytes.size() + got > kMaxInputFileBytes) {
            reason = "larger than the 1 GiB limit for input files";
            return false;
        }
        bytes.append(block, got);
        if (std::any_of(block, block + got, [](char c) {
                return c != '\x1a' && is_forbidden_control(static_cast<unsigned char>(c));
            })) {
            break;
        }
    }
    if (std::ferror(file.get()) != 0) {
        reason = errno_reason(errno == 0 ? EIO : errno);
        return false;
    }
    return true;
}

// Whether the file can be opened, or why not.
bool can_open(const std::filesystem::path& path, std::string& reason) {
    return open_for_reading(path, reason) != nullptr;
}

// Binary junk is refused up front, so no reader ever sees a NUL or a stray control byte.
void check_is_text(SourceText& text) {
    if (!text.bytes.empty() && text.bytes.back() == '\x1a') {
        text.bytes.pop_back();
    }
    const auto bad = std::find_if(text.bytes.begin(), text.bytes.end(), [](char c) {
        return is_forbidden_control(static_cast<unsigned char>(c));
    });
    if (bad == text.bytes.end()) {
        return;
    }
    const int line = 1 + static_cast<int>(std::count(text.bytes.begin(), bad, '\n'));
    const unsigned code = static_cast<unsigned char>(*bad);
    const std::string what =
        code == 0 ? "NUL byte" : fmt::format("control character {:#04x}", code);
    throw InputError(text.at(line), "unexpected " + what + "; this is not a text file");
}

// The classic Mac OS ended lines with a CR alone: each lone CR becomes a line end, so that such
// a file reads as it reads anywhere else (and its errors name the right lines). CRLF stays.
void end_lines_at_lone_carriage_returns(SourceText& text) {
    std::string& b = text.bytes;
    for (std::size_t i = b.find('\r'); i != std::string::npos; i = b.find('\r', i + 1)) {
        if (i + 1 == b.size() || b[i + 1] != '\n') {
            b[i] = '\n';
        }
    }
}

bool oversized(const std::filesystem::path& path) {
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    return !ec && size > kMaxInputFileBytes;
}

}  // namespace

int SourceText::last_line() const {
    const int newlines = static_cast<int>(std::count(bytes.begin(), bytes.end(), '\n'));
    const bool ends_with_newline = !bytes.empty() && bytes.back() == '\n';
    return std::max(1, ends_with_newline ? newlines : newlines + 1);
}

SourceText read_scene_file(const std::filesystem::path& path) {
    SourceText text{path.string(), {}};
    std::string reason = "larger than the 1 GiB limit for input files";
    if (oversized(path) || !read_bytes(path, text.bytes, reason)) {
        throw InputError(SourceLocation{text.name, 0, 0}, "cannot open the scene file: " + reason);
    }
    end_lines_at_lone_carriage_returns(text);
    check_is_text(text);
    return text;
}

SourceText read_named_file(const std::filesystem::path& path, const std::string& kind,
                           const std::string& written, const SourceLocation& named_at) {
    SourceText text{path.string(), {}};
    std::string reason = "larger than the 1 GiB limit for input files";
    if (oversized(path) || !read_bytes(path, text.bytes, reason)) {
        throw InputError(
            named_at, "cannot open " + kind + " '" + written + "' (" + text.name + "): " + reason);
    }
    end_lines_at_lone_carriage_returns(text);
    check_is_text(text);
    return text;
}

void check_named_file(const std::filesystem::path& path, const std::string& kind,
                      const std::string& written, const SourceLocation& named_at) {
    std::string reason = "larger than the 1 GiB limit for input files";
    if (oversized(path) || !can_open(path, reason)) {
        throw InputError(named_at, "cannot open " + kind + " '" + written + "' (" + path.string() +
                                       "): " + reason);
    }
}

}  // namespace rt
