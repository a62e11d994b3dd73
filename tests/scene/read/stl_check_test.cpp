// STL files that Assimp 5.2 would take as neither binary nor ASCII, or read cut short, are refused
// before it reads them, saying what is wrong; good files of either kind still load.
#include "rt/scene/read/stl_check.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "model_files.h"
#include "model_reader_fixture.h"

namespace rt::test {
namespace {

// An 80-byte header, a little-endian count, then `bytes` bytes of facets.
std::string binary_stl(const std::string& header, std::uint32_t count, std::size_t bytes) {
    std::string out = header;
    out.resize(80, ' ');
    out.append(reinterpret_cast<const char*>(&count), 4);
    return out + std::string(bytes, '\0');
}

TEST_F(ModelReader, ABinaryStlLoadsWhateverItsHeaderSays) {
    EXPECT_EQ(read("m.stl", binary_tetra_stl("binary tetra")).polygons.size(), 4u);
    // Many exporters start the header with "solid": the size decides, as in Assimp.
    EXPECT_EQ(read("m.stl", binary_tetra_stl("solid tetra, binary")).polygons.size(), 4u);
}

TEST_F(ModelReader, ABinaryStlMustBeAsLongAsItsCountSays) {
    EXPECT_EQ(error("m.stl", binary_stl("binary", 12, 516)),
              "m.stl: a binary STL of 12 triangles needs 684 bytes (80-byte header, 4-byte count, "
              "50 bytes a triangle), found 600");
    // Cut short, with a header Assimp would take for ASCII.
    EXPECT_EQ(error("m.stl", binary_tetra_stl("solid tetra").substr(0, 274)),
              "m.stl: a binary STL of 4 triangles needs 284 bytes (80-byte header, 4-byte count, "
              "50 bytes a triangle), found 274");
    EXPECT_EQ(error("m.stl", std::string(40, '\0')),
              "m.stl: expected a binary STL of at least 84 bytes, or an ASCII STL starting with "
              "'solid', found 40 bytes");
    EXPECT_EQ(error("m.stl", ""),
              "m.stl: expected a binary STL of at least 84 bytes, or an ASCII STL starting with "
              "'solid', found 0 bytes");
    // A count whose size Assimp's 32-bit sum wraps round to the file's (2^32 + 288 bytes).
    EXPECT_EQ(error("m.stl", binary_stl("solid", 85899350, 204)),
              "m.stl: a binary STL of 85899350 triangles needs 4294967584 bytes (80-byte header, "
              "4-byte count, 50 bytes a triangle), found 288");
    EXPECT_EQ(error("m.stl", std::string(20, 'v') + " 0 0 0\n" + std::string(80, ' ')),
              "m.stl:1: expected 'solid' to start an ASCII STL, found 'vvvvvvvvvvvvvvvvvvvv'");
}

TEST_F(ModelReader, AnAsciiStlCutShortIsRefusedAtItsFirstFault) {
    const auto first_lines = [](int n) {
        std::size_t end = 0;
        for (int i = 0; i < n; ++i) {
            end = tetra_stl.find('\n', end) + 1;
        }
        return tetra_stl.substr(0, end);
    };
    // Assimp read these with a warning at most, or refused them naming no place.
    EXPECT_EQ(error("m.stl", first_lines(29)),
              "m.stl:29: expected 'facet' or 'endsolid', found end of file");
    EXPECT_EQ(error("m.stl", first_lines(26)), "m.stl:26: expected 'vertex', found end of file");
    EXPECT_EQ(error("m.stl", first_lines(22) + "facet normal 1 1"),
              "m.stl:23: expected 3 numbers after 'facet normal', found end of file");
    EXPECT_EQ(error("m.stl", "solid t\n"),
              "m.stl:1: expected 'facet' or 'endsolid', found end of file");
    // Faults inside: a facet without its normal, a coordinate that is no number, two vertices.
    std::string s = tetra_stl;
    EXPECT_EQ(error("m.stl", s.replace(s.find("facet normal 0 -1 0"), 19, "facet")),
              "m.stl:10: expected 'normal', found 'outer'");
    s = tetra_stl;
    EXPECT_EQ(error("m.stl", s.replace(s.find("vertex 1 0 0"), 12, "vertex 1 O 0")),
              "m.stl:6: expected 3 numbers after 'vertex', found 'O'");
    s = tetra_stl;
    EXPECT_EQ(error("m.stl", s.erase(s.find("vertex 1 0 0\nendloop"), 13)),
              "m.stl:6: expected 'vertex', found 'endloop'");
    // Assimp 5.2 compares keywords as written: it reads no "SOLID" and skips "FACET".
    std::string upper = tetra_stl;
    std::transform(upper.begin(), upper.end(), upper.begin(),
                   [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    EXPECT_EQ(error("m.stl", upper),
              "m.stl:1: expected 'solid', found 'SOLID' (Assimp reads STL keywords in lowercase "
              "only)");
    EXPECT_EQ(error("m.stl", "solid T\n" + upper.substr(upper.find('\n') + 1)),
              "m.stl:2: expected 'facet' or 'endsolid', found 'FACET' (Assimp reads STL keywords "
              "in lowercase only)");
}

TEST_F(ModelReader, AsciiStlsLoadAsAssimpReadsThem) {
    // Several solids, one without a name; blanks, CRLF line ends, and words after the last solid.
    std::string unnamed = tetra_stl;
    unnamed.replace(0, 11, "solid").replace(unnamed.find("endsolid tetra"), 14, "endsolid");
    std::string crlf;
    for (const char c : "  " + tetra_stl) {
        crlf += c == '\n' ? std::string("\r\n\t") : std::string(1, c);
    }
    EXPECT_EQ(read("m.stl", tetra_stl + unnamed + crlf + "written by a tool\n").polygons.size(),
              12u);
    // A name of several words, and a file on one line.
    std::string one_line = tetra_stl;
    std::replace(one_line.begin(), one_line.end(), '\n', ' ');
    EXPECT_EQ(
        read("m.stl", "solid Mesh 1\n" + tetra_stl.substr(tetra_stl.find('\n') + 1) + one_line)
            .polygons.size(),
        8u);
    // A facet of 4 vertices: Assimp takes the first 3 and logs an error, a warning here.
    std::string four = tetra_stl;
    four.insert(four.find("endloop"), "vertex 1 1 0\n");
    EXPECT_EQ(read("m.stl", four).polygons.size(), 4u);
    const std::vector<std::string> w = warnings();
    EXPECT_NE(std::find(w.begin(), w.end(),
                        "m.stl: STL: a facet with more than 3 vertices has been found"),
              w.end());
}

}  // namespace
}  // namespace rt::test
