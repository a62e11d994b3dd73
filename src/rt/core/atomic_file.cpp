#include "rt/core/atomic_file.h"

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
    const std::filesystem::path tmp = temporary_beside(path);
    try {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) {
            throw IoError("cannot write " + path.string() + ": cannot create " + tmp.string());
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
