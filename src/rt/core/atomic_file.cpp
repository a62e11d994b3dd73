#include "rt/core/atomic_file.h"

#include <cerrno>
#include <fstream>
#include <string>
#include <system_error>

#include "rt/core/error.h"

#include <unistd.h>

namespace rt {

namespace {

std::filesystem::path temporary_beside(const std::filesystem::path& path) {
    std::filesystem::path tmp = path;
    tmp += ".tmp" + std::to_string(::getpid());
    return tmp;
}

}  // namespace

void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write) {
    // The rename would replace a device, a pipe or a socket with a file: refused, as rt's checks
    // before a render refuse it (a link to one counts as one).
    std::error_code looked;
    const std::filesystem::file_status there = std::filesystem::status(path, looked);
    if (std::filesystem::exists(there) && !std::filesystem::is_regular_file(there) &&
        !std::filesystem::is_directory(there)) {
        throw IoError("cannot write " + path.string() +
                      ": it is a device, a pipe or a socket, not a file");
    }
    const std::filesystem::path tmp = temporary_beside(path);
    try {
        errno = 0;
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) {
            // The stream says only that it failed; the open underneath left the reason in errno.
            const int reason = errno;
            throw IoError("cannot write " + path.string() + ": cannot create " + tmp.string() +
                          (reason != 0 ? ": " + std::generic_category().message(reason) : ""));
        }
        write(out);
        out.flush();
        if (!out) {
            throw IoError("cannot write " + path.string() + ": write failed (disk full?)");
        }
        out.close();
        std::error_code ec;
        std::filesystem::rename(tmp, path, ec);
        if (ec) {
            throw IoError("cannot write " + path.string() + ": " + ec.message());
        }
    } catch (...) {
        std::error_code ignored;
        std::filesystem::remove(tmp, ignored);
        throw;
    }
}

}  // namespace rt
