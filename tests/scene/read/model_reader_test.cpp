// Filetype 3: model files read through Assimp keep their polygons whole, join vertices, give
// their normals and materials, and refuse broken files with one clear message.
#include "rt/scene/read/model_reader.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "model_files.h"
#include "model_reader_fixture.h"
#include "reader_test_support.h"

namespace rt::test {
namespace {

namespace fs = std::filesystem;

TEST_F(ModelReader, AQuadAndAPentagonStayWholeInObjAndPly) {
    for (const auto& [name, text] :
         {std::pair{"m.obj", quad_pentagon_obj}, std::pair{"m.ply", quad_pentagon_ply}}) {
        SCOPED_TRACE(name);
        const SurfaceMesh m = read(name, text);
        EXPECT_EQ(corner_counts(m), (std::vector<std::uint32_t>{4, 5}));
        ASSERT_EQ(m.vertices.size(), 9u);
        EXPECT_EQ(m.vertices[m.corners[6]], (Vec3{3.5, 0.5, 0}));  // the pentagon's third corner
        EXPECT_TRUE(m.corner_normals.empty());
    }
}

TEST_F(ModelReader, DashDfTracesWhatTheModelHolds) {
    RecordingDiagnostics d(true);
    const fs::path path = dir_.write("cube.obj", face_normal_cube_obj);
    read_model_file(path, "cube.obj", {"s.scn", 21, 0}, d.diagnostics);
    ASSERT_EQ(d.traces.size(), 1u);
    EXPECT_EQ(local(d.traces[0]),
              "cube.obj: model: 6 polygons, 8 vertex positions, 0 materials, normals");
}

TEST_F(ModelReader, VerticesAtOnePositionAreJoinedWhateverTheirNormals) {
    const SurfaceMesh m = read("cube.obj", face_normal_cube_obj);
    EXPECT_EQ(m.vertices.size(), 8u);  // not the 24 the file's (position, normal) pairs make
    EXPECT_EQ(corner_counts(m), (std::vector<std::uint32_t>(6, 4)));
    EXPECT_TRUE(warnings().empty()) << warnings().front();  // a closed cube is watertight
}

TEST_F(ModelReader, TheFilesNormalsAreCornerNormalsAndDecideTheOutside) {
    const SurfaceMesh m = read("cube.obj", face_normal_cube_obj);
    ASSERT_EQ(m.corner_normals.size(), m.corners.size());
    EXPECT_EQ(m.corner_normals[0], (Vec3{0, 0, -1}));
    EXPECT_EQ(m.polygons[0].outward, (Vec3{0, 0, -4}));  // the sum of its corners' normals
    EXPECT_EQ(m.corner_normals[20], (Vec3{1, 0, 0}));    // the first corner of the sixth face
}

TEST_F(ModelReader, CornersWithoutNormalsGetZeroBesideCornersWithThem) {
    const SurfaceMesh m = read("m.obj",
                               "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 5 0 0\nv 6 0 0\nv 6 1 0\n"
                               "vn 0 0.6 0.8\nf 1 2 3\nf 4//1 5//1 6//1\n");
    ASSERT_EQ(m.corner_normals.size(), 6u);
    EXPECT_EQ(m.corner_normals[0], Vec3{});
    EXPECT_NEAR(m.corner_normals[3].y, 0.6, 1e-7);
    EXPECT_NEAR(m.corner_normals[3].z, 0.8, 1e-7);
}

TEST_F(ModelReader, MaterialsAreOffsetsInTheMtlsOrder) {
    dir_.write("m.mtl", "newmtl white\nKd 1 1 1\nnewmtl red\nKd 1 0 0\nnewmtl green\nKd 0 1 0\n");
    const SurfaceMesh m = read("m.obj",
                               "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                               "usemtl green\nf 1 3 4\nusemtl white\nf 1 2 4\n"
                               "usemtl red\nf 2 3 4\n");
    ASSERT_EQ(m.materials.size(), 3u);
    EXPECT_EQ(m.materials[0].name, "white");
    EXPECT_EQ(m.materials[2].name, "green");
    ASSERT_TRUE(m.materials[1].diffuse.has_value());
    EXPECT_EQ(m.materials[1].diffuse->r, 1.0);
    EXPECT_EQ(m.materials[1].diffuse->g, 0.0);
    std::vector<long> offsets;
    for (const MeshPolygon& p : m.polygons) {
        offsets.push_back(p.attribute_offset);
    }
    EXPECT_EQ(offsets, (std::vector<long>{2, 0, 1}));
}

TEST_F(ModelReader, WithoutMaterialsEveryOffsetIs0) {
    for (const auto& [name, text] :
         {std::pair{"m.obj", quad_pentagon_obj}, std::pair{"m.ply", quad_pentagon_ply}}) {
        SCOPED_TRACE(name);
        const SurfaceMesh m = read(name, text);
        EXPECT_TRUE(m.materials.empty());  // Assimp's stand-in material is not the file's
        for (const MeshPolygon& p : m.polygons) {
            EXPECT_EQ(p.attribute_offset, 0);
        }
    }
}

TEST_F(ModelReader, AnOpenModelIsWarnedAbout) {
    read("m.obj", quad_pentagon_obj);
    EXPECT_EQ(warnings(), (std::vector<std::string>{
                              "m.obj: the model is not watertight: 9 edges border one polygon "
                              "only"}));
}

TEST_F(ModelReader, AnEdgeOfThreePolygonsIsWarnedAbout) {
    // Three triangles on the edge 1-2; their other six edges border one each.
    read("m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n");
    EXPECT_EQ(warnings(), (std::vector<std::string>{
                              "m.obj: the model is not watertight: 6 edges border one polygon "
                              "only, 1 edge borders more than two"}));
}

TEST_F(ModelReader, ALoopOfManyCornersThroughOneCornerTwiceIsSkipped) {
    // 20 corners on a circle, the loop passing through the first twice.
    std::string obj;
    for (int k = 0; k < 20; ++k) {
        obj += fmt::format("v {} {} 0\n", std::cos(k * 0.314159), std::sin(k * 0.314159));
    }
    obj += "f";
    for (int k = 1; k <= 20; ++k) {
        obj += fmt::format(" {}", k);
    }
    obj += " 1 10\nf";
    for (int k = 1; k <= 20; ++k) {
        obj += fmt::format(" {}", k);
    }
    obj += "\n";
    const SurfaceMesh m = read("m.obj", obj);
    ASSERT_EQ(m.polygons.size(), 1u);
    EXPECT_EQ(m.polygons[0].corner_count, 20u);
    const std::vector<std::string> w = warnings();
    EXPECT_EQ(w.front(), "m.obj: polygon 0 passes through one corner twice; skipped");
}

TEST_F(ModelReader, PointsAndLinesAreSkippedWithAWarning) {
    const SurfaceMesh m = read("m.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\nl 1 2\np 3\n");
    EXPECT_EQ(m.polygons.size(), 1u);
    const std::vector<std::string> w = warnings();
    EXPECT_NE(std::find(w.begin(), w.end(),
                        "m.obj: 2 faces with fewer than 3 corners (points or lines) skipped"),
              w.end());
}

TEST_F(ModelReader, ARepeatedCornerIsDroppedAndALoopThroughOneCornerTwiceSkipped) {
    const SurfaceMesh m = read("m.obj",
                               "v 0 0 0\nv 1 0 0\nv 1 0 0\nv 1 1 0\nv 2 2 0\nv 0 2 0\n"
                               "f 1 2 3 4\nf 1 2 4 5 4 6\n");
    ASSERT_EQ(m.polygons.size(), 1u);  // vertices 2 and 3 are one position: a triangle
    EXPECT_EQ(m.polygons[0].corner_count, 3u);
    const std::vector<std::string> w = warnings();
    EXPECT_EQ(w.front(), "m.obj: polygon 1 passes through one corner twice; skipped");
}

TEST_F(ModelReader, GltfNodeTransformsPlaceTheMesh) {
    // One triangle, placed twice: moved by 10 in x, and mirrored in x (which reverses its loop
    // so that its right-hand-rule side stays the outside).
    const std::string gltf = R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0,1]}],
"nodes":[{"mesh":0,"translation":[10,0,0]},{"mesh":0,"scale":[-1,1,1]}],
"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
"buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":36}],
"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}]})";
    const SurfaceMesh m = read("m.gltf", gltf);
    ASSERT_EQ(m.polygons.size(), 2u);
    const auto corner = [&](std::size_t p, std::uint32_t k) {
        return m.vertices[m.corners[m.polygons[p].first_corner + k]];
    };
    EXPECT_EQ(corner(0, 0), (Vec3{10, 0, 0}));
    EXPECT_EQ(corner(0, 1), (Vec3{11, 0, 0}));
    EXPECT_EQ(corner(0, 2), (Vec3{10, 1, 0}));
    EXPECT_EQ(corner(1, 0), (Vec3{0, 1, 0}));  // reversed: (0,1,0) (-1,0,0) (0,0,0)
    EXPECT_EQ(corner(1, 1), (Vec3{-1, 0, 0}));
    EXPECT_EQ(corner(1, 2), (Vec3{0, 0, 0}));
}

// The PLY body walked as its header lays it out, before Assimp reserves room for what it claims.
TEST_F(ModelReader, APlyBodyMustBeWhatItsHeaderSays) {
    const std::string header =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
        "property float y\nproperty float z\nelement face 1\n"
        "property list uchar int vertex_indices\nend_header\n";
    // A list count a 220-byte file cannot hold: Assimp took 2 GB for it.
    std::string binary = header;
    binary.replace(binary.find("ascii"), 5, "binary_little_endian");
    binary.replace(binary.find("uchar"), 5, "uint");
    binary += std::string(36, '\0') + std::string("\x00\x00\x00\x10", 4) + std::string(12, '\0');
    EXPECT_EQ(error("m.ply", binary),
              "m.ply: face element 0 has a list of 268435456 items: expected 0 to 100000");
    EXPECT_EQ(error("m.ply", header + "0 0 0\n1 0 0\n0 1 0\n4294967295 0 1 2\n"),
              "m.ply:13: expected the list count of face element 0 (0 to 100000), found "
              "'4294967295'");
    // Fewer elements than promised, and a line short of its properties.
    EXPECT_EQ(error("m.ply", header + "0.25 0.25 0.25\n1.25 0.25 0.25\n0.25 1.25 0.25\n"),
              "m.ply:12: the file ends in face element 0 of the 1 its header promises (the file is "
              "truncated or its header is wrong)");
    EXPECT_EQ(error("m.ply", header + "0 0 0\n1 0\n0 1 0\n3 0 1 2\n"),
              "m.ply:11: expected 3 numbers in vertex element 1 (as the header lays it out), found "
              "2");
    std::string no_x = header;
    no_x.replace(no_x.find("property float x"), 16, "property float w");
    EXPECT_EQ(error("m.ply", no_x + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
              "m.ply: the vertex element has no property x");
}

// Assimp reads a face's vertex numbers as unsigned: -5 was named as vertex 4294967291.
TEST_F(ModelReader, APlyFaceMustReferToVerticesTheFileHas) {
    const std::string header =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
        "property float y\nproperty float z\nelement face 2\n"
        "property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    EXPECT_EQ(error("m.ply", header + "3 0 -5 2\n"),
              "m.ply:14: face element 1 refers to vertex -5: expected 0 to 2");
    EXPECT_EQ(error("m.ply", header + "3 0 3 2\n"),
              "m.ply:14: face element 1 refers to vertex 3: expected 0 to 2");
    EXPECT_EQ(error("m.ply", header + "3 0 one 2\n"),
              "m.ply:14: face element 1 refers to vertex 'one': expected 0 to 2");
    // The same in binary, read as the list's item type says (signed int, unsigned short).
    std::string binary = header.substr(0, header.find("0 0 0\n"));
    binary.replace(binary.find("ascii"), 5, "binary_little_endian");
    binary.replace(binary.find("face 2"), 6, "face 1");
    std::string vertices;
    for (const float c : {0.F, 0.F, 0.F, 1.F, 0.F, 0.F, 0.F, 1.F, 0.F}) {
        vertices.append(reinterpret_cast<const char*>(&c), sizeof c);  // a little-endian host
    }
    EXPECT_EQ(error("m.ply",
                    binary + vertices + std::string("\x03\0\0\0\0\x01\0\0\0\xfb\xff\xff\xff", 13)),
              "m.ply: face element 0 refers to vertex -5: expected 0 to 2");
    std::string ushort = binary;
    ushort.replace(ushort.find("uchar int"), 9, "uchar ushort");
    EXPECT_EQ(error("m.ply", ushort + vertices + std::string("\x03\0\0\x01\0\x07\0", 7)),
              "m.ply: face element 0 refers to vertex 7: expected 0 to 2");
    EXPECT_EQ(
        read("m.ply", ushort + vertices + std::string("\x03\0\0\x01\0\x02\0", 7)).polygons.size(),
        1u);
}

TEST_F(ModelReader, BrokenFilesGiveOneClearMessage) {
    EXPECT_EQ(error("m.ply",
                    std::string(quad_pentagon_ply).replace(quad_pentagon_ply.rfind('8'), 1, "18")),
              "m.ply:21: face element 1 refers to vertex 18: expected 0 to 8");
    EXPECT_EQ(error("m.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 7\n"),
              "m.obj: cannot read the model: OBJ: vertex index out of range");
    EXPECT_EQ(error("m.ply", ""), "m.ply: cannot read the model: File m.ply is empty.");
    EXPECT_EQ(error("m.ply", "ply\nformat ascii 1.0\nend_header\n"),
              "m.ply: cannot read the model: Invalid .ply file: Unable to extract mesh data");
    EXPECT_EQ(error("m.obj", "# nothing but a comment\n"), "m.obj: the model holds no polygons");
    // A coordinate that is no number, or far out, is named as the file has it.
    EXPECT_EQ(error("m.obj", "v nan 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n"),
              "m.obj: vertex 0 of mesh 'defaultobject': expected coordinates from -1e+15 to "
              "1e+15, found (nan, 0, 0)");
    EXPECT_EQ(error("m.obj", "v 0 0 0\nv 1 2251799813685248 0\nv 1 1 0\nf 1 2 3\n"),
              "m.obj: vertex 1 of mesh 'defaultobject': expected coordinates from -1e+15 to "
              "1e+15, found (1, 2251799813685248, 0)");
    EXPECT_EQ(error("m.ply", "\x7f\x45\x4c\x46 binary junk\n"),
              "m.ply: cannot read the model: Invalid .ply file: Incorrect magic number (expected "
              "'ply' or 'PLY').");
    EXPECT_EQ(error("m.xyz", "v 0 0 0\n"),
              "s.scn:21: optical surface file 'm.xyz' has filetype 3 (a model file), but '.xyz' "
              "is no model format Assimp reads (.obj, .ply, .stl, .gltf, .glb, .off, ...)");
    EXPECT_EQ(
        local(input_error([&] {
            read_model_file(dir_.path() / "none.obj", "none.obj", {"s.scn", 21, 0}, diagnostics_);
        })),
        "s.scn:21: cannot open optical surface file 'none.obj' (none.obj): No such file or "
        "directory");
}

TEST_F(ModelReader, AHeaderPromisingMoreThanTheFileHoldsIsRefusedBeforeReading) {
    EXPECT_EQ(error("m.ply",
                    "ply\nformat binary_little_endian 1.0\nelement vertex 400000000\n"
                    "property float x\nproperty float y\nproperty float z\n"
                    "end_header\n"),
              "m.ply:3: the header promises 400000000 vertex elements, more than the limit of "
              "50000000");
    EXPECT_EQ(error("m.ply",
                    "ply\nformat binary_little_endian 1.0\nelement vertex 4000\n"
                    "property float x\nproperty float y\nproperty float z\n"
                    "end_header\n"),
              "m.ply:3: the header promises 4000 vertex elements, but the 0 bytes after it hold "
              "at most 0 (the file is truncated or its header is wrong)");
    EXPECT_EQ(error("m.ply",
                    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                    "end_heade"),
              "m.ply:5: the PLY header has no end_header line ending in a line break");
    EXPECT_EQ(error("m.ply", "ply\nformat ascii 1.0\nelement vertex many\nend_header\n"),
              "m.ply:3: expected the count of the vertex elements, found 'many'");
    EXPECT_EQ(error("m.ply",
                    "ply\nformat binary_little_endian 1.0\nelement vertex 3\n"
                    "property float x\nend_header"),
              "m.ply:5: the PLY header has no end_header line ending in a line break");
    EXPECT_EQ(error("m.off", "OFF\n4000 3000 0\n0 0 0\n"),
              "m.off:2: the header promises 4000 vertices, but the 22 bytes after it hold at "
              "most 3 (the file is truncated or its header is wrong)");
}

// Assimp 5.2 skips an OFF face line without a corner count by lowering its face count, and a few
// of them make it read past its faces (fuzz/regressions/model/assimp-off-face-without-count).
TEST_F(ModelReader, AnOffFaceWithoutItsCornerCountIsRefusedBeforeAssimp) {
    EXPECT_EQ(error("m.off", "OFF\n3 3 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\nv 0 0 0\nv 1 0 0\n"),
              "m.off:7: expected face 1: a corner count from 1, then as many vertex numbers (0 "
              "to 2); found 'v 0 0 0'");
    EXPECT_EQ(error("m.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1\n"),
              "m.off:6: expected face 0: a corner count from 1, then as many vertex numbers (0 "
              "to 2); found '3 0 1'");
    // A vertex the file does not have (Assimp clamps it), and fewer faces than promised (Assimp
    // renders what there is).
    EXPECT_EQ(error("m.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 9\n"),
              "m.off:7: expected face 0: a corner count from 1, then as many vertex numbers (0 "
              "to 3); found '4 0 1 2 9'");
    EXPECT_EQ(error("m.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n"),
              "m.off:7: the file ends after 1 of the 2 faces its header promises (the file is "
              "truncated or its header is wrong)");
}

TEST_F(ModelReader, WhatAssimpRepairsIsWarnedAbout) {
    // Past the first 64 KB the face lines are Assimp's alone: its OFF reader clamps an index out
    // of range instead of refusing it.
    std::string off = "OFF\n4000 1 0\n";
    for (int v = 0; v < 4000; ++v) {
        off += "0.000000 0.000000 " + std::to_string(v) + ".000000\n";
    }
    off += "3 0 1 9999\n";
    ASSERT_GT(off.size(), std::size_t{64} * 1024);
    read("m.off", off);
    const std::vector<std::string> w = warnings();
    EXPECT_NE(std::find(w.begin(), w.end(), "m.off: OFF: Vertex index is out of range"), w.end());
}

}  // namespace
}  // namespace rt::test
