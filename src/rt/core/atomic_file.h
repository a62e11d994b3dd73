// Writes a file so that an existing one is never replaced by a partial or broken one.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>

namespace rt {

/// Calls write(stream) on a temporary file beside path, then renames it over path. If write
/// throws or the stream fails, the temporary is removed, path is untouched, and the error
/// propagates (an IoError for stream failures).
void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write);

}  // namespace rt
