// Small model files for the filetype-3 tests, written as their tools would write them.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>

namespace rt::test {

/// A unit quad (z = 0, normal +z) and a pentagon beside it, as OBJ.
inline const std::string quad_pentagon_obj = R"(# a quad and a pentagon
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 2 0 0
v 3 0 0
v 3.5 0.5 0
v 3 1 0
v 2 1 0
f 1 2 3 4
f 5 6 7 8 9
)";

/// The same two polygons as ASCII PLY.
inline const std::string quad_pentagon_ply = R"(ply
format ascii 1.0
comment a quad and a pentagon
element vertex 9
property float x
property float y
property float z
element face 2
property list uchar int vertex_indices
end_header
0 0 0
1 0 0
1 1 0
0 1 0
2 0 0
3 0 0
3.5 0.5 0
3 1 0
2 1 0
4 0 1 2 3
5 4 5 6 7 8
)";

/// A unit cube with one normal per face (so 24 vertices as the file lists them, 8 positions).
inline const std::string face_normal_cube_obj = R"(v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
v 1 0 1
v 1 1 1
v 0 1 1
vn 0 0 -1
vn 0 0 1
vn 0 -1 0
vn 0 1 0
vn -1 0 0
vn 1 0 0
f 1//1 4//1 3//1 2//1
f 5//2 6//2 7//2 8//2
f 1//3 2//3 6//3 5//3
f 4//4 8//4 7//4 3//4
f 1//5 5//5 8//5 4//5
f 2//6 3//6 7//6 6//6
)";

/// A tetrahedron (corners at the origin and the three unit points) as ASCII STL.
inline const std::string tetra_stl = R"(solid tetra
facet normal 0 0 -1
outer loop
vertex 0 0 0
vertex 0 1 0
vertex 1 0 0
endloop
endfacet
facet normal 0 -1 0
outer loop
vertex 0 0 0
vertex 1 0 0
vertex 0 0 1
endloop
endfacet
facet normal -1 0 0
outer loop
vertex 0 0 0
vertex 0 0 1
vertex 0 1 0
endloop
endfacet
facet normal 1 1 1
outer loop
vertex 1 0 0
vertex 0 1 0
vertex 0 0 1
endloop
endfacet
endsolid tetra
)";

/// The same tetrahedron as binary STL: `header` padded to 80 bytes, the count, 4 facets of 50
/// bytes (a little-endian host).
inline std::string binary_tetra_stl(const std::string& header) {
    const float facets[4][12] = {{0, 0, -1, 0, 0, 0, 0, 1, 0, 1, 0, 0},
                                 {0, -1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1},
                                 {-1, 0, 0, 0, 0, 0, 0, 0, 1, 0, 1, 0},
                                 {1, 1, 1, 1, 0, 0, 0, 1, 0, 0, 0, 1}};
    std::string out = header;
    out.resize(80, ' ');
    const std::uint32_t count = 4;
    out.append(reinterpret_cast<const char*>(&count), 4);
    for (const auto& facet : facets) {
        out.append(reinterpret_cast<const char*>(facet), sizeof facet);
        out.append(2, '\0');  // the attribute byte count
    }
    return out;
}

/// One triangle as glTF, its positions in the JSON (base64), one member a line.
inline const std::string triangle_gltf = R"({
"asset": {"version": "2.0"},
"scene": 0,
"scenes": [{"nodes": [0]}],
"nodes": [{"mesh": 0}],
"meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
"buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
"bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}],
"accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]}]
}
)";

/// A little-endian 32-bit number as 4 bytes (a little-endian host).
inline std::string le32(std::uint32_t n) {
    return {reinterpret_cast<const char*>(&n), 4};
}

/// The same triangle as binary glTF: the JSON chunk (padded with blanks), then the BIN chunk of
/// its positions.
inline std::string triangle_glb() {
    std::string json = triangle_gltf;
    json.replace(json.find(", \"uri\""),
                 json.find("}]", json.find("\"uri\"")) - json.find(", \"uri\""), "");
    json.resize((json.size() + 3) / 4 * 4, ' ');
    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const std::string bin(reinterpret_cast<const char*>(positions), sizeof positions);
    const std::string chunks = le32(static_cast<std::uint32_t>(json.size())) + "JSON" + json +
                               le32(static_cast<std::uint32_t>(bin.size())) +
                               std::string("BIN\0", 4) + bin;
    return "glTF" + le32(2) + le32(static_cast<std::uint32_t>(12 + chunks.size())) + chunks;
}

}  // namespace rt::test
