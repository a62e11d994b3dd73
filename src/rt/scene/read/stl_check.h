// Assimp 5.2's STL reader takes a file as binary when its size is 84 + 50 N bytes (N the count
// after the 80-byte header), else as ASCII when it starts with "solid", else it gives up with
// "Failed to determine STL storage representation". Its ASCII reader skips words it does not
// know, reads a file cut short as far as it goes, or refuses it naming no place ("STL: Invalid
// number of vertices"). This check names what is wrong first.
#pragma once

#include <filesystem>
#include <string>

namespace rt {

/// Checks an STL file before Assimp reads it. A file Assimp would take as neither binary nor ASCII
/// is refused with what it lacks: "name: a binary STL of 12 triangles needs 684 bytes (...), found
/// 600". An ASCII file is walked, streamed, solid by solid (solid, then facets of facet normal,
/// outer loop, 3 or more vertices, endloop and endfacet, then endsolid): its first fault, the
/// end of the file included, is "name:line: expected ..., found ...".
void check_stl(const std::filesystem::path& path, const std::string& name);

}  // namespace rt
