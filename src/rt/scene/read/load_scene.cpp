#include "rt/scene/read/load_scene.h"

#include <map>
#include <unordered_map>

#include "rt/scene/read/attributes_reader.h"
#include "rt/scene/read/scene_builder.h"
#include "rt/scene/read/scn_reader.h"
#include "rt/scene/read/shape_reader.h"
#include "rt/scene/read/surface_reader.h"
#include "rt/scene/read/textured_surface.h"

namespace rt {

namespace {

// Numbers the files read, in Scene::source_files, each name once.
class FileTable {
public:
    explicit FileTable(Scene& scene) : scene_(scene) {
        for (std::uint32_t i = 0; i < scene_.source_files.size(); ++i) {
            index_.emplace(scene_.source_files[i], i);
        }
    }
    std::uint32_t index(const std::string& name) {
        const auto [it, fresh] =
            index_.emplace(name, static_cast<std::uint32_t>(scene_.source_files.size()));
        if (fresh) {
            scene_.source_files.push_back(name);
        }
        return it->second;
    }

private:
    Scene& scene_;
    std::unordered_map<std::string, std::uint32_t> index_;
};

SourceText read_listed_file(Scene& scene, const std::filesystem::path& folder,
                            const NamedFile& named, const std::string& kind) {
    SourceText text = read_named_file(folder / named.name, kind, named.name, named.where);
    FileTable(scene).index(text.name);
    return text;
}

// A file named by several surfaces is read once and kept until its last use.
class MeshCache {
public:
    MeshCache(const std::vector<ScnSurface>& surfaces, const std::filesystem::path& folder)
        : folder_(folder) {
        for (const ScnSurface& s : surfaces) {
            ++uses_left_[key(s.surface)];
        }
    }
    template <typename Read>
    const SurfaceMesh& get(const OpticalSurface& surface, Read read) {
        const auto k = key(surface);
        auto it = meshes_.find(k);
        if (it == meshes_.end()) {
            it = meshes_.emplace(k, read()).first;
        }
        return it->second;
    }
    void done_with(const OpticalSurface& surface) {
        const auto k = key(surface);
        if (--uses_left_[k] == 0) {
            meshes_.erase(k);
        }
    }

private:
    std::pair<std::string, int> key(const OpticalSurface& s) const {
        return {(folder_ / s.file).string(), s.filetype};
    }
    std::filesystem::path folder_;
    std::map<std::pair<std::string, int>, int> uses_left_;
    std::map<std::pair<std::string, int>, SurfaceMesh> meshes_;
};

void add_surfaces(Scene& scene, const ScnFile& scn, const std::filesystem::path& folder,
                  const ReaderDialect& dialect, const PictureCheck& check_pictures,
                  Diagnostics& diagnostics) {
    SceneBuilder builder(scene, diagnostics);
    TexturePictures pictures{check_pictures, {}, {}};
    MeshCache cache(scn.surfaces, folder);
    FileTable files(scene);
    for (const ScnSurface& entry : scn.surfaces) {
        const OpticalSurface& s = entry.surface;
        const std::filesystem::path path = folder / s.file;
        const std::uint32_t file = files.index(path.string());
        const SurfaceMesh& mesh = cache.get(s, [&] {
            if (diagnostics.tracing()) {
                diagnostics.trace(s.where.to_string() + ": reading optical surface file '" +
                                  s.file + "' (" + path.string() + "), filetype " +
                                  std::to_string(s.filetype));
            }
            return read_optical_surface(path, s, dialect, diagnostics);
        });
        builder.add_surface(entry, mesh, file);
        cache.done_with(s);
    }
    for (const ScnTexturedSurface& entry : scn.textured_surfaces) {
        const NamedFile& grid = entry.polygon_file;
        const NamedFile& map = entry.texture_map;
        const std::uint32_t file = files.index((folder / grid.name).string());
        files.index((folder / map.name).string());  // read too: a render's input (--resume)
        add_textured_surface(
            builder, scene, entry,
            read_named_file(folder / grid.name, "polygon file", grid.name, grid.where),
            read_named_file(folder / map.name, "texture map", map.name, map.where), file, pictures,
            diagnostics);
    }
    builder.finish(scn.eye_at);
}

}  // namespace

Scene load_scene(const std::filesystem::path& scn_file, const ReaderDialect& dialect,
                 Diagnostics& diagnostics, const PictureCheck& check_pictures) {
    const SourceText scn_text = read_scene_file(scn_file);
    ScnFile scn = read_scn(scn_text, dialect, diagnostics);
    const std::filesystem::path folder = scn_file.parent_path();
    Scene scene;
    scene.scene_file = scn_file;
    scene.header = scn.header;
    scene.view = scn.view;
    scene.source_files.push_back(scn_text.name);
    if (scn.attributes_file) {
        const SourceText text =
            read_listed_file(scene, folder, *scn.attributes_file, "the attributes file");
        scene.attributes = read_attributes_file(text, dialect, diagnostics);
    } else {
        scene.attributes = std::move(scn.inline_attributes);
    }
    if (scn.shape_file) {
        const SourceText text = read_listed_file(scene, folder, *scn.shape_file, "the shape file");
        scene.shapes = read_shape_file(text, diagnostics);
    }
    // The scene's big arrays are already in memory advised for huge pages: SceneBuilder reserves
    // them so (reserve_more), and copying them again (move_to_huge_pages) would only cost time.
    add_surfaces(scene, scn, folder, dialect, check_pictures, diagnostics);
    diagnostics.finish_repeats();
    return scene;
}

}  // namespace rt
