// Flattens placed optical surfaces into the Scene (manual 2.2, 2.5): world positions shared within
// a surface, oriented unit normals, attributes and shapes looked up by number, degenerate polygons
// skipped with a warning; then vertex normals for smooth shading and auto-centering.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <map>
#include <unordered_map>
#include <utility>

#include "rt/core/diagnostics.h"
#include "rt/scene/read/scn_reader.h"
#include "rt/scene/read/surface_mesh.h"
#include "rt/scene/read/surface_transform.h"
#include "rt/scene/scene.h"

namespace rt {

class SceneBuilder {
public:
    /// The scene must already hold its attributes and the shape file's shapes; the builder
    /// replaces Scene::shapes with world-space copies of the shapes polygons use.
    SceneBuilder(Scene& scene, Diagnostics& diagnostics);

    /// Room in the scene's arrays for all of these meshes, when the caller has them all before
    /// adding any: the arrays are then filled in place, never copied as they grow.
    void reserve_for(std::initializer_list<const SurfaceMesh*> meshes);

    /// Adds the polygons of one optical surface read from source_files[file].
    void add_surface(const ScnSurface& entry, const SurfaceMesh& mesh, std::uint32_t file);

    /// Vertex normals, auto-centering (header center 1) and the empty-scene warning.
    void finish(const SourceLocation& eye_at);

private:
    struct Placing;  // the state of one add_surface call

    void add_polygon(Placing& placing, const MeshPolygon& polygon);
    void add_corner_normals(const Placing& placing, const MeshPolygon& polygon,
                            std::uint32_t first_corner);
    std::uint32_t attribute_index(const Placing& placing, const MeshPolygon& polygon) const;
    std::int32_t shape_index(Placing& placing, const MeshPolygon& polygon);
    /// The vertex's place in Scene::positions, placing it on first use; an error at its line
    /// (or the polygon's) when it lands outside kMaxCoordinate.
    std::uint32_t position_index(Placing& placing, const MeshPolygon& polygon,
                                 std::uint32_t vertex);
    /// Where the vertex is placed; the same error as position_index when outside kMaxCoordinate.
    Vec3 placed_within_range(const Placing& placing, const MeshPolygon& polygon,
                             std::uint32_t vertex) const;
    SourceLocation polygon_location(const Placing& placing, const MeshPolygon& polygon) const;

    Scene& scene_;
    Diagnostics& diagnostics_;
    std::unordered_map<long, std::uint32_t> attribute_by_number_;
    std::vector<Shape> file_shapes_;
};

/// Per position, the normalised area-weighted sum of the normals of the smooth polygons using it;
/// zero where no smooth polygon does.
void compute_vertex_normals(Scene& scene);

}  // namespace rt
