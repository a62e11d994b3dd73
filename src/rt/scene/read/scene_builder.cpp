#include "rt/scene/read/scene_builder.h"

#include <algorithm>
#include <limits>
#include <vector>

#include "rt/core/huge_pages.h"
#include "rt/scene/polygon_geometry.h"
#include "rt/scene/read/field_reader.h"
#include "rt/scene/read/reader_limits.h"

#include <fmt/format.h>

namespace rt {

namespace {

constexpr std::size_t kMaxIndex = std::numeric_limits<std::uint32_t>::max();
constexpr std::uint32_t kUnplaced = std::numeric_limits<std::uint32_t>::max();

const char* shape_kind(PolygonMark mark) {
    return mark == PolygonMark::Sphere     ? "sphere"
           : mark == PolygonMark::Cylinder ? "cylinder"
                                           : "cone";
}

// A shape's numbers must make sense for the kind a polygon's mark gives it.
void check_shape_use(const Shape& s, PolygonMark mark, const SourceLocation& used_at) {
    const std::string use = fmt::format("shape {} is used as a {} by {}", s.index, shape_kind(mark),
                                        used_at.to_string());
    if (mark == PolygonMark::Cone) {
        if (!(s.radius_or_angle > 0 && s.radius_or_angle < 90)) {
            throw InputError(s.where, use + ", but its half-angle " +
                                          show_number(s.radius_or_angle) +
                                          " is not between 0 and 90 degrees");
        }
    } else if (!(s.radius_or_angle > 0)) {
        throw InputError(s.where, use + ", but its radius " + show_number(s.radius_or_angle) +
                                      " is not positive");
    }
    if (mark != PolygonMark::Sphere && s.first == s.second) {
        throw InputError(s.where, use + ", but its two axis points are the same");
    }
}

// Room for `more` elements beyond v's size, growing at least geometrically: reserving exactly what
// each surface adds would copy the arrays once per surface. The room is advised for huge pages
// (core/huge_pages.h) as it is reserved, so that a big scene's arrays, which every intersection
// method reads at random, need no copy into such memory after.
template <class T>
void reserve_more(std::vector<T>& v, std::size_t more) {
    if (v.capacity() - v.size() < more) {
        reserve_whole_huge_pages(v, std::max(v.size() + more, 2 * v.capacity()));
    }
}

std::string out_of_range(std::string_view what, const Vec3& from, const Vec3& to) {
    return fmt::format("{} {} is placed at {}, outside the coordinate range {:g} to {:g}", what,
                       show_point(from.x, from.y, from.z), show_point(to.x, to.y, to.z),
                       -kMaxCoordinate, kMaxCoordinate);
}

}  // namespace

struct SceneBuilder::Placing {
    const ScnSurface& entry;
    const SurfaceMesh& mesh;
    std::uint32_t surface = 0;
    std::uint32_t file = 0;
    SurfaceTransform transform;
    std::vector<std::uint32_t> position_of;               ///< per mesh vertex, or kUnplaced
    std::map<std::pair<long, int>, std::int32_t> shapes;  ///< (shape number, mark) -> Scene::shapes
};

SceneBuilder::SceneBuilder(Scene& scene, Diagnostics& diagnostics)
    : scene_(scene), diagnostics_(diagnostics), file_shapes_(std::move(scene.shapes)) {
    scene_.shapes.clear();
    for (std::uint32_t i = 0; i < scene_.attributes.size(); ++i) {
        attribute_by_number_.emplace(scene_.attributes[i].index, i);
    }
}

void SceneBuilder::add_surface(const ScnSurface& entry, const SurfaceMesh& mesh,
                               std::uint32_t file) {
    const SurfacePlacement& p = entry.placement;
    Placing placing{entry,
                    mesh,
                    static_cast<std::uint32_t>(scene_.surfaces.size()),
                    file,
                    SurfaceTransform(p.scale, p.rotation_degrees, p.translation),
                    std::vector<std::uint32_t>(mesh.vertices.size(), kUnplaced),
                    {}};
    scene_.surfaces.push_back(entry.surface);
    // Room for the whole surface first: a million-polygon model's arrays were otherwise copied
    // into fresh memory at every doubling.
    reserve_for({&mesh});
    for (const MeshPolygon& polygon : mesh.polygons) {
        add_polygon(placing, polygon);
    }
}

void SceneBuilder::reserve_for(std::initializer_list<const SurfaceMesh*> meshes) {
    std::size_t polygons = 0;
    std::size_t corners = 0;
    std::size_t vertices = 0;
    for (const SurfaceMesh* mesh : meshes) {
        polygons += mesh->polygons.size();
        corners += mesh->corners.size();
        vertices += mesh->vertices.size();
    }
    reserve_more(scene_.polygons, polygons);
    reserve_more(scene_.polygon_origin, polygons);
    reserve_more(scene_.corners, corners);
    reserve_more(scene_.positions, vertices);
}

SourceLocation SceneBuilder::polygon_location(const Placing& placing,
                                              const MeshPolygon& polygon) const {
    return {scene_.source_files[placing.file], polygon.line, 0};
}

void SceneBuilder::add_polygon(Placing& placing, const MeshPolygon& polygon) {
    const std::span<const std::uint32_t> loop(placing.mesh.corners.data() + polygon.first_corner,
                                              polygon.corner_count);
    Vec3 n = newell_normal(loop, placing.mesh.vertices);
    if (const std::string_view why = degeneracy(loop, placing.mesh.vertices, n); !why.empty()) {
        // A vertex placed out of range is the real mistake (one far corner alone can make the
        // area vanish in the rounding); the check costs nothing on polygons that pass.
        for (const std::uint32_t vertex : loop) {
            placed_within_range(placing, polygon, vertex);
        }
        const SourceLocation at = polygon_location(placing, polygon);
        diagnostics_.warn_repeated(fmt::format("degenerate polygons in {}", at.file),
                                   fmt::format("{}: polygon {} is degenerate ({}); skipped",
                                               at.to_string(), polygon.number, why));
        return;
    }
    // The file's outward direction decides the side; without one (zero, or in the plane) the
    // loop's own right-hand-rule normal stands.
    const double agreement = dot(normalize(n), polygon.outward);
    if (agreement < -1e-9 * length(polygon.outward)) {
        n = -n;
    }
    if (scene_.corners.size() + loop.size() > kMaxIndex || scene_.polygons.size() >= kMaxIndex) {
        throw InputError(placing.entry.surface.where, "the scene has too many polygons");
    }
    Polygon out;
    out.first_corner = static_cast<std::uint32_t>(scene_.corners.size());
    out.corner_count = polygon.corner_count;
    out.normal = normalize(placing.transform.normal(n));
    out.attribute = attribute_index(placing, polygon);
    out.surface = placing.surface;
    out.mark = polygon.mark;
    out.shape = shape_index(placing, polygon);
    out.smooth =
        placing.entry.surface.smooth_shaded || polygon.mark == PolygonMark::InterpolatesNormals;
    out.texture_cell = polygon.texture_cell;
    for (const std::uint32_t vertex : loop) {
        scene_.corners.push_back(position_index(placing, polygon, vertex));
    }
    if (out.smooth && !placing.mesh.corner_normals.empty()) {
        add_corner_normals(placing, polygon, out.first_corner);
    }
    scene_.polygons.push_back(out);
    scene_.polygon_origin.push_back({placing.file, static_cast<std::uint32_t>(polygon.line)});
}

// A model file's normals, placed like the polygon; the corners before them that have none get
// zero, which defers to the vertex normals (Scene::model_normals).
void SceneBuilder::add_corner_normals(const Placing& placing, const MeshPolygon& polygon,
                                      std::uint32_t first_corner) {
    scene_.model_normals.resize(first_corner, Vec3{});
    for (std::uint32_t k = 0; k < polygon.corner_count; ++k) {
        const Vec3 n =
            placing.transform.normal(placing.mesh.corner_normals[polygon.first_corner + k]);
        const double l = length(n);
        scene_.model_normals.push_back(l > 0 ? n / l : Vec3{});
    }
}

std::uint32_t SceneBuilder::attribute_index(const Placing& placing,
                                            const MeshPolygon& polygon) const {
    const OpticalSurface& surface = placing.entry.surface;
    long number = 0;
    // A sum that overflows names no attribute; it must not wrap round onto one.
    const bool overflow =
        __builtin_add_overflow(surface.attribute_number, polygon.attribute_offset, &number);
    const auto it = overflow ? attribute_by_number_.end() : attribute_by_number_.find(number);
    if (it != attribute_by_number_.end()) {
        return it->second;
    }
    if (overflow) {
        throw InputError(
            polygon_location(placing, polygon),
            fmt::format("polygon {} uses attribute {} + offset {}, which is not defined",
                        polygon.number, surface.attribute_number, polygon.attribute_offset));
    }
    if (polygon.attribute_offset == 0) {
        throw InputError(surface.where, fmt::format("optical surface '{}' uses attribute {}, which "
                                                    "is not defined",
                                                    surface.file, number));
    }
    throw InputError(
        polygon_location(placing, polygon),
        fmt::format("polygon {} uses attribute {} (attribute {} of the optical surface "
                    "+ offset {}), which is not defined",
                    polygon.number, number, surface.attribute_number, polygon.attribute_offset));
}

// Shapes are written in the coordinates of the polygons that use them (manual 2.4), so each
// surface gets its own world-space copy of each shape it uses.
std::int32_t SceneBuilder::shape_index(Placing& placing, const MeshPolygon& polygon) {
    const PolygonMark mark = polygon.mark;
    if (mark == PolygonMark::Ordinary || mark == PolygonMark::InterpolatesNormals) {
        return Polygon::kNoShape;
    }
    const auto key = std::make_pair(polygon.shape_number, static_cast<int>(mark));
    if (const auto it = placing.shapes.find(key); it != placing.shapes.end()) {
        return it->second;
    }
    const SourceLocation at = polygon_location(placing, polygon);
    if (polygon.shape_number < 0 || polygon.shape_number >= std::ssize(file_shapes_)) {
        throw InputError(
            at, fmt::format("polygon {} (mark {}, a {}) refers to shape {}, but the "
                            "shape file defines {} (numbered from 0)",
                            polygon.number, static_cast<int>(mark), shape_kind(mark),
                            polygon.shape_number, count_of(std::ssize(file_shapes_), "shape")));
    }
    Shape shape = file_shapes_[static_cast<std::size_t>(polygon.shape_number)];
    check_shape_use(shape, mark, at);
    const SurfaceTransform& t = placing.transform;
    for (Vec3* p : {&shape.first, &shape.second}) {
        const Vec3 placed = t.point(*p);
        if (!within_coordinate_range(placed)) {
            throw InputError(shape.where, out_of_range(fmt::format("shape {}'s point", shape.index),
                                                       *p, placed));
        }
        *p = placed;
    }
    if (mark != PolygonMark::Cone) {
        shape.radius_or_angle *= std::fabs(t.scale());  // a cone's angle survives a uniform scale
        if (!(shape.radius_or_angle <= kMaxCoordinate)) {
            throw InputError(
                shape.where,
                fmt::format("shape {}'s radius is placed at {}, more than {:g}", shape.index,
                            show_number(shape.radius_or_angle), kMaxCoordinate));
        }
    }
    scene_.shapes.push_back(shape);
    const auto index = static_cast<std::int32_t>(scene_.shapes.size() - 1);
    placing.shapes.emplace(key, index);
    return index;
}

std::uint32_t SceneBuilder::position_index(Placing& placing, const MeshPolygon& polygon,
                                           std::uint32_t vertex) {
    std::uint32_t& slot = placing.position_of[vertex];
    if (slot == kUnplaced) {
        const Vec3 placed = placed_within_range(placing, polygon, vertex);
        slot = static_cast<std::uint32_t>(scene_.positions.size());
        scene_.positions.push_back(placed);
    }
    return slot;
}

Vec3 SceneBuilder::placed_within_range(const Placing& placing, const MeshPolygon& polygon,
                                       std::uint32_t vertex) const {
    const Vec3& p = placing.mesh.vertices[vertex];
    const Vec3 placed = placing.transform.point(p);
    // Every placed coordinate stays within range, so that the world's extent, the voxel sizes
    // and Embree's float rays stay finite.
    if (!within_coordinate_range(placed)) {
        const std::vector<int>& lines = placing.mesh.vertex_lines;
        const SourceLocation at =
            vertex < lines.size()
                ? SourceLocation{scene_.source_files[placing.file], lines[vertex], 0}
                : polygon_location(placing, polygon);
        throw InputError(
            at, out_of_range("the vertex", p, placed) +
                    fmt::format(" by optical surface '{}' ({})", placing.entry.surface.file,
                                placing.entry.surface.where.to_string()));
    }
    return placed;
}

}  // namespace rt
