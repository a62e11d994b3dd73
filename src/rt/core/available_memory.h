// The memory this process may still take, read from the system before anything big is
// allocated: rt's render check (app/memory_estimate.h) and the window's (window/picture_window.h)
// ask it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace rt {

/// The memory this process may still take: the least of MemAvailable (/proc/meminfo), the cgroup's
/// memory.max less its memory.current, and RLIMIT_AS less the address space in use. Empty when
/// none can be read.
struct MemoryLimit {
    std::uint64_t bytes = 0;
    std::string source;  ///< "MemAvailable in /proc/meminfo", "--max-memory"
};
std::optional<MemoryLimit> available_memory();

/// "3.2 GiB", "512 MiB".
std::string format_bytes(std::uint64_t bytes);

}  // namespace rt
