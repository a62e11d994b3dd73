// A fresh temporary folder per test, removed afterwards; tests never write anywhere else.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace rt::test {

class TempDir {
public:
    TempDir();
    ~TempDir();
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    const std::filesystem::path& path() const { return path_; }
    /// Writes text to a file in the folder and returns its path.
    std::filesystem::path write(const std::string& name, const std::string& text) const;

private:
    std::filesystem::path path_;
};

/// The source tree (for shipped scenes and test data): $RT_SOURCE_DIR or the compiled-in path.
std::filesystem::path source_dir();
/// Where the built programs are: $RT_BIN_DIR.
std::filesystem::path bin_dir();
/// Reads a whole file.
std::string read_text(const std::filesystem::path& path);
/// The lines of a text, without their line ends.
std::vector<std::string> lines_of(const std::string& text);

}  // namespace rt::test
