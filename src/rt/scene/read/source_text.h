// A whole input file in memory, checked to be text, with the name its messages use.
#pragma once

#include <filesystem>
#include <string>

#include "rt/core/error.h"

namespace rt {

struct SourceText {
    std::string name;   ///< as shown in messages: "scenes/cube"
    std::string bytes;  ///< the whole file; a final Ctrl-Z (MS-DOS end of file) is dropped

    /// The line of the file's last character (1 for an empty file): where "end of file" is.
    int last_line() const;
    SourceLocation at(int line, int column = 0) const { return {name, line, column}; }
};

/// Reads the .scn file itself. A file that cannot be read is an InputError naming it.
SourceText read_scene_file(const std::filesystem::path& path);

/// Reads a file the .scn (or -Df block) names at `named_at`, e.g. kind "optical surface file",
/// written "cube": a failure reads "twocubes.scn:21: cannot open optical surface file 'cube'
/// (scenes/cube): No such file or directory".
SourceText read_named_file(const std::filesystem::path& path, const std::string& kind,
                           const std::string& written, const SourceLocation& named_at);

/// Checks, with read_named_file's message, that a file the .scn names can be opened and is within
/// the size limit, without reading it: for the binary formats a library reads (model files).
void check_named_file(const std::filesystem::path& path, const std::string& kind,
                      const std::string& written, const SourceLocation& named_at);

}  // namespace rt
