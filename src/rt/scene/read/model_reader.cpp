#include "rt/scene/read/model_reader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <memory>
#include <mutex>

#include "rt/core/huge_pages.h"
#include "rt/scene/read/assimp_functions.h"
#include "rt/scene/read/field_reader.h"
#include "rt/scene/read/gltf_check.h"
#include "rt/scene/read/model_header_check.h"
#include "rt/scene/read/model_mesh_check.h"
#include "rt/scene/read/node_transform.h"
#include "rt/scene/read/reader_limits.h"
#include "rt/scene/read/source_text.h"
#include "rt/scene/read/stl_check.h"

#include <fmt/format.h>

#include <assimp/cimport.h>
#include <assimp/material.h>
#include <assimp/scene.h>

namespace rt {

namespace {

// Assimp's logger is one per process: model files are read one at a time.
std::mutex assimp_mutex;

// Keeps what Assimp logs (errors and warnings) instead of letting it print, so that its
// complaints about a file it still reads (OFF: "Vertex index is out of range") become warnings.
// The first stream attached creates Assimp's logger (no file, no other stream); the last one
// detached deletes it.
class AssimpLog {
public:
    explicit AssimpLog(const AssimpFunctions& assimp) : assimp_(assimp) {
        stream_.callback = &AssimpLog::write;
        stream_.user = static_cast<char*>(static_cast<void*>(&messages_));
        assimp_.aiEnableVerboseLogging(AI_FALSE);
        assimp_.aiAttachLogStream(&stream_);
    }
    ~AssimpLog() { assimp_.aiDetachLogStream(&stream_); }
    AssimpLog(const AssimpLog&) = delete;
    AssimpLog& operator=(const AssimpLog&) = delete;
    const std::vector<std::string>& messages() const { return messages_; }

private:
    // A stream of the C API hears every severity the logger lets through (info too): only the
    // errors and warnings are kept, as their prefix says ("Error, T0: ", "Warn,  T0: ").
    static void write(const char* message, char* user) noexcept {
        auto& out = *static_cast<std::vector<std::string>*>(static_cast<void*>(user));
        try {
            std::string m(message);
            if (!m.starts_with("Error, ") && !m.starts_with("Warn, ")) {
                return;
            }
            // "Error, T0: OFF: Vertex index is out of range\n" -> "OFF: Vertex index ..."
            if (const std::size_t at = m.find(": "); at < 20) {  // npos is not
                m.erase(0, at + 2);
            }
            while (!m.empty() && (m.back() == '\n' || m.back() == '\r')) {
                m.pop_back();
            }
            if (std::find(out.begin(), out.end(), m) == out.end()) {
                out.push_back(m);
            }
        } catch (...) {  // NOLINT(bugprone-empty-catch): nothing may leave for Assimp's C code
        }
    }

    const AssimpFunctions& assimp_;
    aiLogStream stream_{};
    std::vector<std::string> messages_;
};

// A scene from aiImportFileExWithProperties, released (with its importer) by aiReleaseImport.
class SceneRelease {
public:
    explicit SceneRelease(const AssimpFunctions& assimp) : release_(assimp.aiReleaseImport) {}
    void operator()(const aiScene* scene) const { release_(scene); }

private:
    decltype(AssimpFunctions::aiReleaseImport) release_;
};
using ImportedScene = std::unique_ptr<const aiScene, SceneRelease>;

std::string lower_extension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

// PLY and OFF headers are checked before Assimp trusts their counts; STL files before Assimp
// fails to tell binary from ASCII, or reads a file cut short; glTF files before Assimp fails to
// parse their JSON ("No suitable reader found").
void check_header(const std::filesystem::path& path, const std::string& ext,
                  const std::string& name) {
    if (ext == ".stl") {
        check_stl(path, name);
    } else if (ext == ".gltf") {
        check_gltf(path, name);
    } else if (ext == ".glb") {
        check_glb(path, name);
    }
    if (ext != ".ply" && ext != ".off") {
        return;
    }
    std::ifstream in(path, std::ios::binary);
    std::string head(std::size_t{64} * 1024, '\0');
    in.read(head.data(), static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<std::size_t>(in.gcount()));
    const std::uintmax_t size = std::filesystem::file_size(path);
    if (ext == ".ply") {
        check_ply_header(head, size, name);
        check_ply_body(path, name);
    } else {
        check_off_header(head, size, name);
    }
}

// Attribute offsets per Assimp material: the file's own materials count from 0 in Assimp's order;
// the stand-in Assimp adds for faces that name none takes offset 0 and no place (OBJ and STL call
// it DefaultMaterial, PLY and OFF leave it unnamed, glTF appends it unnamed after the others).
std::vector<long> material_offsets(const AssimpFunctions& assimp, const aiScene& scene, bool gltf,
                                   SurfaceMesh& mesh) {
    std::vector<long> offsets(scene.mNumMaterials, 0);
    for (unsigned i = 0; i < scene.mNumMaterials; ++i) {
        const aiMaterial& m = *scene.mMaterials[i];
        aiString ai_name;  // empty when the material has none (what aiMaterial::GetName() does)
        assimp.aiGetMaterialString(&m, AI_MATKEY_NAME, &ai_name);
        const std::string name = ai_name.C_Str();
        const bool stand_in =
            gltf ? i + 1 == scene.mNumMaterials : name.empty() || name == AI_DEFAULT_MATERIAL_NAME;
        if (stand_in) {
            continue;
        }
        offsets[i] = static_cast<long>(mesh.materials.size());
        MeshMaterial material{name, std::nullopt};
        if (aiColor4D c;
            assimp.aiGetMaterialColor(&m, AI_MATKEY_COLOR_DIFFUSE, &c) == aiReturn_SUCCESS) {
            material.diffuse = Rgb{c.r, c.g, c.b};
        }
        mesh.materials.push_back(material);
    }
    return offsets;
}

// Assimp's row-major 4x4 (float); its last row is 0 0 0 1 for the transforms models use.
NodeTransform::Matrix3x4 rows_of(const aiMatrix4x4& m) {
    return {{{m.a1, m.a2, m.a3, m.a4}, {m.b1, m.b2, m.b3, m.b4}, {m.c1, m.c2, m.c3, m.c4}}};
}

// Walks Assimp's node tree, placing each mesh a node names with the node's accumulated transform
// (glTF places meshes by nodes; OBJ, PLY, STL and OFF have one identity node).
class ModelFlattener {
public:
    ModelFlattener(const AssimpFunctions& assimp, const aiScene& scene, std::string name, bool gltf)
        : scene_(scene), name_(std::move(name)) {
        offsets_ = material_offsets(assimp, scene, gltf, mesh_);
    }

    SurfaceMesh flatten() {
        add_node(*scene_.mRootNode, NodeTransform{}, 0);
        return std::move(mesh_);
    }
    /// Faces of fewer than 3 corners (points and lines) are not optical surfaces.
    long short_faces() const { return short_faces_; }

private:
    void add_node(const aiNode& node, const NodeTransform& parent, int depth);
    void add_mesh(const aiMesh& m, const NodeTransform& t);
    InputError error(const std::string& message) const { return {{name_, 0, 0}, message}; }

    const aiScene& scene_;
    std::string name_;
    SurfaceMesh mesh_;
    std::vector<long> offsets_;
    long faces_seen_ = 0;
    long short_faces_ = 0;
    bool any_normals_ = false;
};

void ModelFlattener::add_node(const aiNode& node, const NodeTransform& parent, int depth) {
    if (depth > 1000) {
        throw error("the model's nodes nest more than 1000 deep");
    }
    const NodeTransform t = parent.then(rows_of(node.mTransformation));
    for (unsigned i = 0; i < node.mNumMeshes; ++i) {
        if (node.mMeshes[i] >= scene_.mNumMeshes) {
            throw error(fmt::format("node '{}' names mesh {}, but the model has {}",
                                    node.mName.C_Str(), node.mMeshes[i], scene_.mNumMeshes));
        }
        add_mesh(*scene_.mMeshes[node.mMeshes[i]], t);
    }
    for (unsigned i = 0; i < node.mNumChildren; ++i) {
        add_node(*node.mChildren[i], t, depth + 1);
    }
}

void ModelFlattener::add_mesh(const aiMesh& m, const NodeTransform& t) {
    if (mesh_.vertices.size() + m.mNumVertices > static_cast<std::size_t>(kMaxItemsPerFile) ||
        static_cast<std::int64_t>(mesh_.polygons.size()) + m.mNumFaces > kMaxItemsPerFile) {
        throw error(
            fmt::format("the model has more than {} vertices or polygons", kMaxItemsPerFile));
    }
    if (m.mMaterialIndex >= offsets_.size()) {
        throw error(fmt::format("mesh '{}' uses material {}, but the model has {}", m.mName.C_Str(),
                                m.mMaterialIndex, offsets_.size()));
    }
    const auto base = static_cast<std::uint32_t>(mesh_.vertices.size());
    // Room for the whole mesh first: growing by doubling copied a million-polygon model's arrays
    // into fresh memory again and again. In huge pages: the polygon records alone are 72 MB for
    // a million triangles, and each 4 KiB page of fresh memory is a page fault of its own.
    std::size_t corners = 0;
    for (unsigned f = 0; f < m.mNumFaces; ++f) {
        corners += std::min<std::size_t>(m.mFaces[f].mNumIndices, kMaxEdgesPerPolygon + 1);
    }
    reserve_whole_huge_pages(mesh_.vertices, mesh_.vertices.size() + m.mNumVertices);
    reserve_whole_huge_pages(mesh_.polygons, mesh_.polygons.size() + m.mNumFaces);
    reserve_whole_huge_pages(mesh_.corners, mesh_.corners.size() + corners);
    if (any_normals_ || m.HasNormals()) {
        reserve_whole_huge_pages(mesh_.corner_normals, mesh_.corners.size() + corners);
    }
    for (unsigned v = 0; v < m.mNumVertices; ++v) {
        const aiVector3D& p = m.mVertices[v];
        const Vec3 placed = t.point({p.x, p.y, p.z});
        // NaN, inf or a coordinate far out would wreck the framing's scale, and the range check
        // after placement would then name some healthy vertex: named here, as the file has it.
        if (!within_coordinate_range(placed)) {
            throw error(fmt::format(
                "vertex {} of mesh '{}': expected coordinates from {:g} to "
                "{:g}, found {}",
                v, m.mName.C_Str(), -kMaxCoordinate, kMaxCoordinate, show_point(p.x, p.y, p.z)));
        }
        mesh_.vertices.push_back(placed);
    }
    const bool normals = m.HasNormals();
    std::vector<std::uint32_t> loop;
    for (unsigned f = 0; f < m.mNumFaces; ++f) {
        const aiFace& face = m.mFaces[f];
        const long number = faces_seen_++;
        if (face.mNumIndices < 3) {
            ++short_faces_;
            continue;
        }
        if (face.mNumIndices > kMaxEdgesPerPolygon) {
            throw error(fmt::format("polygon {} has {} corners, more than the limit of {}", number,
                                    face.mNumIndices, kMaxEdgesPerPolygon));
        }
        MeshPolygon p;
        p.number = number;
        p.attribute_offset = offsets_[m.mMaterialIndex];
        loop.clear();
        for (unsigned k = 0; k < face.mNumIndices; ++k) {
            // A mirroring transform turns the loop's sense round; reversing keeps it outward.
            const unsigned i = face.mIndices[t.mirrors() ? face.mNumIndices - 1 - k : k];
            if (i >= m.mNumVertices) {
                throw error(
                    fmt::format("polygon {} refers to vertex {}, but its mesh has {} "
                                "vertices (numbered from 0)",
                                number, i, m.mNumVertices));
            }
            loop.push_back(base + i);
            const Vec3 n =
                normals ? t.direction({m.mNormals[i].x, m.mNormals[i].y, m.mNormals[i].z}) : Vec3{};
            p.outward += n;  // the side the file's normals point to is outside
            if (normals && !any_normals_) {
                any_normals_ = true;
                mesh_.corner_normals.assign(mesh_.corners.size(), Vec3{});
            }
            if (any_normals_) {
                mesh_.corner_normals.push_back(n);
            }
        }
        mesh_.add_polygon(p, loop);
    }
}

ImportedScene import_model(const AssimpFunctions& assimp, const std::filesystem::path& path,
                           const std::string& name) {
    try {
        // No post-processing: no triangulation (n-gons keep their normal interpolation), and
        // joining and node transforms are done here (Assimp's joining keeps vertices apart that
        // differ in normal, and reads out of bounds on an index out of range). No properties.
        ImportedScene scene(
            assimp.aiImportFileExWithProperties(path.string().c_str(), 0, nullptr, nullptr),
            SceneRelease(assimp));
        if (scene == nullptr) {
            std::string why = assimp.aiGetErrorString();
            while (!why.empty() && std::isspace(static_cast<unsigned char>(why.back())) != 0) {
                why.pop_back();
            }
            throw InputError({name, 0, 0}, "cannot read the model: " + why);
        }
        return scene;
    } catch (const std::bad_alloc&) {
        throw InputError({name, 0, 0}, "cannot read the model: out of memory");
    }
}

// Assimp's functions, loaded the first time a model is read; a library that cannot be loaded is
// the model's error.
const AssimpFunctions& assimp_for(const std::string& name) {
    try {
        return assimp_functions();
    } catch (const Error& e) {
        throw InputError({name, 0, 0}, fmt::format("cannot read the model: {}", e.what()));
    }
}

}  // namespace

SurfaceMesh read_model_file(const std::filesystem::path& path, const std::string& written,
                            const SourceLocation& named_at, Diagnostics& diagnostics) {
    check_named_file(path, "optical surface file", written, named_at);
    const std::string name = path.string();
    const std::string ext = lower_extension(path);
    const AssimpFunctions& assimp = assimp_for(name);
    const std::lock_guard<std::mutex> lock(assimp_mutex);
    if (ext.empty() || assimp.aiIsExtensionSupported(ext.c_str()) == AI_FALSE) {
        throw InputError(
            named_at,
            fmt::format("optical surface file '{}' has filetype 3 (a model file), "
                        "but {} is no model format Assimp reads (.obj, .ply, .stl, "
                        ".gltf, .glb, .off, ...)",
                        written, ext.empty() ? "a name without an extension" : "'" + ext + "'"));
    }
    check_header(path, ext, name);
    SurfaceMesh mesh;
    {
        ImportedScene scene(nullptr, SceneRelease(assimp));  // released after the log is gone
        const AssimpLog log(assimp);
        scene = import_model(assimp, path, name);
        if (scene->mRootNode == nullptr) {
            throw InputError({name, 0, 0}, "the model has no node tree");
        }
        ModelFlattener flattener(assimp, *scene, name, ext == ".gltf" || ext == ".glb");
        mesh = flattener.flatten();
        for (const std::string& m : log.messages()) {
            diagnostics.warn(fmt::format("{}: {}", name, m));
        }
        if (flattener.short_faces() > 0) {
            diagnostics.warn(
                fmt::format("{}: {} with fewer than 3 corners (points or lines) "
                            "skipped",
                            name, count_of(flattener.short_faces(), "face")));
        }
    }
    if (mesh.polygons.empty()) {
        throw InputError({name, 0, 0}, "the model holds no polygons");
    }
    weld_vertices(mesh, name, diagnostics);
    warn_if_not_watertight(mesh, name, diagnostics);
    if (diagnostics.tracing()) {
        diagnostics.trace(fmt::format("{}: model: {}, {}, {}, {}", name,
                                      count_of(std::ssize(mesh.polygons), "polygon"),
                                      count_of(std::ssize(mesh.vertices), "vertex position"),
                                      count_of(std::ssize(mesh.materials), "material"),
                                      mesh.corner_normals.empty() ? "no normals" : "normals"));
    }
    return mesh;
}

}  // namespace rt
