// The flat, loaded scene: what the accelerators, the camera and the shading read. Plain data with
// indices instead of pointers; immutable once load_scene() returns.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "rt/core/bounds.h"
#include "rt/core/error.h"
#include "rt/core/vec3.h"
#include "rt/geometry/camera.h"
#include "rt/geometry/polygon_view.h"
#include "rt/scene/attribute.h"
#include "rt/scene/texture_cell.h"
#include "rt/scene/texture_image.h"

namespace rt {

/// The first $ line of a .scn file (manual 2.2).
struct SceneHeader {
    int center = 0;             ///< 1: auto-centre the look point on the objects
    int lghtick = 0;            ///< shadow feelers: 0 none, 1 emitter vertices, 2 emitter centres
    int sptncde = 0;            ///< 0 brute force, 1 octree, N>1 SEADS with N voxels a side
    int octr = 0;               ///< octree depth (with sptncde 1)
    int graphmode = 0;          ///< unused (was the output device)
    double normallength = 0.0;  ///< length of the wireframe's normals
    int maxdepth = 1;           ///< maximum depth of the ray tree
    double maxdist = 0.0;       ///< depth down to which rays are distributed
};

/// The view of the .scn file (manual 2.2): where the camera stands and what it sees, the samples
/// per pixel and the output matrix.
struct SceneView : CameraPlacement {
    int sample_resolution_x = 1;  ///< at most x*y samples per pixel
    int sample_resolution_y = 1;
    PixelRect window;  ///< the output matrix: the part of the view area to render

    /// The pinhole camera this view describes.
    Camera camera() const { return Camera::placed(*this); }
};

/// Polygon marks of -M (manual 2.5).
enum class PolygonMark : std::uint8_t {
    Ordinary = 0,
    InterpolatesNormals = 1,
    Sphere = 2,
    Cylinder = 3,
    Cone = 4
};

/// A shape of the shape file (manual 2.4): seven numbers whose meaning the polygon's mark picks.
struct Shape {
    Vec3 first;                    ///< sphere centre, a point on a cylinder's axis, a cone's apex
    double radius_or_angle = 0.0;  ///< radius, or the cone's half-angle at the apex in degrees
    Vec3 second;                   ///< another point on the axis (ignored for spheres)
    long index = 0;                ///< the number polygons use to refer to it
    SourceLocation where;
};

struct Polygon {
    std::uint32_t first_corner = 0;  ///< into Scene::corners
    std::uint32_t corner_count = 0;  ///< at least 3
    Vec3 normal;                     ///< unit geometric normal, pointing outward
    std::uint32_t attribute = 0;     ///< into Scene::attributes
    std::uint32_t surface = 0;       ///< into Scene::surfaces
    /// Not an index into Scene::shapes: the polygon's mark uses no shape.
    static constexpr std::int32_t kNoShape = -1;
    PolygonMark mark = PolygonMark::Ordinary;
    std::int32_t shape = kNoShape;  ///< into Scene::shapes, or kNoShape
    bool smooth = false;            ///< interpolate vertex normals (smooth-shade field or mark 1)
    /// Not an index into Scene::texture_cells: the polygon is not texture-mapped.
    static constexpr std::int32_t kNoTexture = -1;
    std::int32_t texture_cell = kNoTexture;  ///< into Scene::texture_cells (-V), or kNoTexture
};

/// Where a polygon came from, so that every later complaint can name a line.
struct SourceRef {
    std::uint32_t file = 0;  ///< into Scene::source_files
    std::uint32_t line = 0;
};

/// One optical surface of an entity as the .scn names it.
struct OpticalSurface {
    std::string file;  ///< as written in the .scn
    int entity = 0;    ///< 1-based entity number
    int filetype = 0;  ///< 0, 1 (Phigs+) or 2 (Prinz polygonizer)
    bool smooth_shaded = false;
    long attribute_number = 0;
    std::string texture_map;  ///< -V: the texture map file; empty for an entity's surface
    SourceLocation where;
};

struct Scene {
    std::filesystem::path scene_file;
    SceneHeader header;
    SceneView view;
    std::vector<Attribute> attributes;
    std::vector<Shape> shapes;
    std::vector<OpticalSurface> surfaces;
    std::vector<Vec3> positions;       ///< world-space vertices, shared by neighbours
    std::vector<Vec3> vertex_normals;  ///< per position: averaged over its smooth polygons
    /// Per corner, or empty: model_normals, and with -E the crease normals of the other corners of
    /// smooth polygons. A non-zero entry overrides vertex_normals at that corner.
    std::vector<Vec3> corner_normals;
    /// Per corner, or empty: the normals a model file (filetype 3) gives its smooth polygons,
    /// placed in the world; zero where it gives none.
    std::vector<Vec3> model_normals;
    std::vector<std::uint32_t> corners;  ///< polygon corners in loop order, into positions
    std::vector<Polygon> polygons;
    std::vector<TextureCell> texture_cells;    ///< the cells of the texture-mapped surfaces (-V)
    std::vector<TextureGrid> texture_grids;    ///< one per texture-mapped surface
    std::vector<TextureImage> texture_images;  ///< the pictures their texture maps name
    std::vector<SourceRef> polygon_origin;     ///< per polygon
    std::vector<std::string> source_files;     ///< files read, for SourceRef

    Vec3 corner_position(const Polygon& p, std::uint32_t k) const {
        return positions[corners[p.first_corner + k]];
    }
    /// Polygon `polygon` as the geometry routines take it (ray_polygon.h).
    PolygonView polygon_view(std::uint32_t polygon) const {
        const Polygon& p = polygons[polygon];
        return {positions, {corners.data() + p.first_corner, p.corner_count}, p.normal};
    }
    /// The normals at polygon `polygon`'s corners (geometry/normals.h): its own where it has them
    /// (a model file's, -E's), else the vertex normals; none when the scene has fewer vertex
    /// normals than positions.
    CornerNormals normals_of(std::uint32_t polygon) const;
    const Attribute& attribute_of(const Polygon& p) const { return attributes[p.attribute]; }
    SourceLocation origin_of(std::uint32_t polygon) const;
    /// Smallest box around every position; a box of no size at the origin for an empty scene
    /// (never an empty box: its infinities would spill into every size derived from it).
    Box3 bounds() const;
};

/// Moves the arrays the intersection methods read per ray (positions, corners, polygons) into
/// memory backed by 2 MiB pages where the system allows (core/huge_pages.h), once the scene is
/// complete: the exact test then misses the TLB less on big meshes. For scenes made by other
/// means than SceneBuilder, which reserves its arrays in such memory from the start.
void move_to_huge_pages(Scene& scene);

}  // namespace rt
