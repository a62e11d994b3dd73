#include "rt/core/available_memory.h"

#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include <sys/resource.h>

namespace rt {

namespace {

// The number after `key` in a "Key: value kB" file such as /proc/meminfo, in bytes.
std::optional<std::uint64_t> kib_field(const std::string& file, const std::string& key) {
    std::ifstream in(file);
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind(key, 0) == 0) {
            std::istringstream fields(line.substr(key.size()));
            std::uint64_t kib = 0;
            if (fields >> kib) {
                return kib * 1024;
            }
        }
    }
    return std::nullopt;
}

// A cgroup v2 file holding one number ("max" when unlimited).
std::optional<std::uint64_t> number_in(const std::string& file) {
    std::ifstream in(file);
    std::uint64_t value = 0;
    if (in >> value) {
        return value;
    }
    return std::nullopt;
}

void take_lower(std::optional<MemoryLimit>& limit, std::uint64_t bytes, const std::string& source) {
    if (!limit || bytes < limit->bytes) {
        limit = MemoryLimit{bytes, source};
    }
}

}  // namespace

std::optional<MemoryLimit> available_memory() {
    std::optional<MemoryLimit> limit;
    if (const auto available = kib_field("/proc/meminfo", "MemAvailable:")) {
        take_lower(limit, *available, "MemAvailable in /proc/meminfo");
    }
    const auto cgroup_max = number_in("/sys/fs/cgroup/memory.max");
    const auto cgroup_used = number_in("/sys/fs/cgroup/memory.current");
    if (cgroup_max && cgroup_used) {
        take_lower(limit, *cgroup_max > *cgroup_used ? *cgroup_max - *cgroup_used : 0,
                   "the cgroup's memory.max");
    }
    rlimit address_space{};
    if (::getrlimit(RLIMIT_AS, &address_space) == 0 && address_space.rlim_cur != RLIM_INFINITY) {
        const std::uint64_t used = kib_field("/proc/self/status", "VmSize:").value_or(0);
        const std::uint64_t cap = address_space.rlim_cur;
        take_lower(limit, cap > used ? cap - used : 0, "the address-space limit (ulimit -v)");
    }
    return limit;
}

std::string format_bytes(std::uint64_t bytes) {
    const double kib = static_cast<double>(bytes) / 1024.0;
    if (kib >= 1024.0 * 1024.0) {
        return fmt::format("{:.1f} GiB", kib / (1024.0 * 1024.0));
    }
    if (kib >= 1024.0) {
        return fmt::format("{:.0f} MiB", kib / 1024.0);
    }
    if (bytes >= 1024) {
        return fmt::format("{:.0f} KiB", kib);
    }
    return fmt::format("{} byte{}", bytes, bytes == 1 ? "" : "s");
}

}  // namespace rt
