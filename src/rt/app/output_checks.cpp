#include "rt/app/output_checks.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <string>
#include <system_error>

#include "rt/app/memory_estimate.h"
#include "rt/core/error.h"

#include <fmt/format.h>

#include <fcntl.h>
#include <sys/statvfs.h>
#include <unistd.h>

namespace rt {

namespace {

std::filesystem::path folder_of(const std::filesystem::path& path) {
    return path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
}

std::string why(int error) {
    return std::generic_category().message(error);
}

// Creates and removes the temporary the atomic writer will create: access() would say yes to
// root in a read-only mount or in /proc.
void try_creating_beside(const std::filesystem::path& path) {
    std::filesystem::path probe = path;
    probe += ".tmp" + std::to_string(::getpid());
    const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd < 0) {
        const int error = errno;
        if (error == EEXIST) {
            return;  // left by an earlier run of the same process id; the writer truncates it
        }
        throw IoError(fmt::format("cannot write {}: cannot create a file in the folder {} ({})",
                                  path.string(), folder_of(path).string(), why(error)));
    }
    ::close(fd);
    ::unlink(probe.c_str());
}

}  // namespace

void check_output_folder(const std::filesystem::path& path) {
    const std::filesystem::path folder = folder_of(path);
    std::error_code ec;
    const std::filesystem::file_status folder_status = std::filesystem::status(folder, ec);
    if (!std::filesystem::exists(folder_status)) {
        throw IoError(fmt::format("cannot write {}: the folder {} does not exist", path.string(),
                                  folder.string()));
    }
    if (!std::filesystem::is_directory(folder_status)) {
        throw IoError(
            fmt::format("cannot write {}: {} is not a folder", path.string(), folder.string()));
    }
    const std::filesystem::file_status target = std::filesystem::status(path, ec);
    if (std::filesystem::exists(target) && !std::filesystem::is_regular_file(target) &&
        !std::filesystem::is_directory(target)) {
        // The writer renames its temporary over the path: it would replace the device itself.
        throw IoError(fmt::format("cannot write {}: it is a device, a pipe or a socket, not a file",
                                  path.string()));
    }
    if (::access(folder.c_str(), W_OK | X_OK) != 0) {
        throw IoError(fmt::format("cannot write {}: the folder {} is not writable ({})",
                                  path.string(), folder.string(), why(errno)));
    }
    try_creating_beside(path);
}

std::uint64_t output_size_bound(const std::filesystem::path& path, const PixelRect& window) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    const std::uint64_t pixels = static_cast<std::uint64_t>(std::max(window.width(), 0)) *
                                 static_cast<std::uint64_t>(std::max(window.height(), 0));
    const std::uint64_t bytes_per_pixel = (ext == ".png" || ext == ".ppm") ? 3 : 12;
    return pixels * bytes_per_pixel;
}

void check_free_space(const std::filesystem::path& path, std::uint64_t needed,
                      std::uint64_t free_bytes) {
    if (needed <= free_bytes) {
        return;
    }
    throw IoError(fmt::format(
        "cannot write {}: the picture takes up to {}, and its folder {} has {} free: free some "
        "space or write it elsewhere",
        path.string(), format_bytes(needed), folder_of(path).string(), format_bytes(free_bytes)));
}

void check_output_space(const std::filesystem::path& path, const PixelRect& window) {
    struct statvfs fs {};
    if (::statvfs(folder_of(path).c_str(), &fs) != 0) {
        return;
    }
    const std::uint64_t blocks = ::geteuid() == 0 ? fs.f_bfree : fs.f_bavail;
    check_free_space(path, output_size_bound(path, window),
                     static_cast<std::uint64_t>(blocks) * fs.f_frsize);
}

}  // namespace rt
