// Assimp's PLY and OFF readers reserve memory for the element counts their headers promise: a
// 200-byte file claiming 400 million vertices makes them take gigabytes and a minute before they
// fail. These checks refuse such a header first, against the file's size and the reader limits.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace rt {

/// Checks the header of a PLY file (`bytes` is its start, at least up to end_header if the file
/// has one; `file_size` its whole size). Throws InputError "name:line: ..." at the element line
/// whose count cannot fit, or at the last line if there is no end_header line ending in a line
/// break (Assimp 5.2 never returns from such a file). Other faults of the header are left to Assimp
/// to refuse.
void check_ply_header(std::string_view bytes, std::uintmax_t file_size, const std::string& name);

/// Walks a PLY file's elements as its header lays them out, without keeping them: throws
/// InputError naming the element when a list's count is negative or above kMaxEdgesPerPolygon
/// (Assimp reserves room for it first: a 220-byte file took 2 GB), or when the data ends before
/// the elements the header promises (Assimp then reads on, or makes up the rest). Run after
/// check_ply_header has accepted the header; a file that is not PLY is left alone.
void check_ply_body(const std::filesystem::path& path, const std::string& name);

/// The same for an OFF file: the vertex and face counts after the optional OFF keyword.
void check_off_header(std::string_view bytes, std::uintmax_t file_size, const std::string& name);

}  // namespace rt
