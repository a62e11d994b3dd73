#include "rt/scene/read/textured_surface.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "rt/image/png_format.h"
#include "rt/scene/polygon_geometry.h"
#include "rt/scene/read/field_reader.h"
#include "rt/scene/read/grid_file_reader.h"
#include "rt/scene/read/reader_limits.h"
#include "rt/scene/read/surface_transform.h"
#include "rt/scene/read/texture_map_reader.h"

#include <fmt/format.h>

namespace rt {

namespace {

std::string cell_name(std::int64_t row, std::int64_t column) {
    return fmt::format("cell (row {}, column {})", row, column);
}

// The cell's corners in loop order: (r, c), (r, c+1), (r+1, c+1), (r+1, c). With u to the right
// and v up, the loop runs counter-clockwise, so the outward side is u x v (right-hand rule).
std::array<std::uint32_t, 4> cell_loop(const PolygonGrid& grid, std::int64_t row,
                                       std::int64_t column) {
    return {static_cast<std::uint32_t>(grid.point_index(row, column)),
            static_cast<std::uint32_t>(grid.point_index(row, column + 1)),
            static_cast<std::uint32_t>(grid.point_index(row + 1, column + 1)),
            static_cast<std::uint32_t>(grid.point_index(row + 1, column))};
}

// A cell is one polygon, so its corners must share a plane (within kCellFlatness of its size).
void check_flat(const SourceText& source, const PolygonGrid& grid, std::int64_t row,
                std::int64_t column, std::span<const std::uint32_t> loop, const Vec3& newell) {
    const Vec3 n = normalize(newell);
    Vec3 centre;
    for (const std::uint32_t k : loop) {
        centre += grid.points[k] / 4.0;
    }
    const double size = std::max(length(grid.points[loop[2]] - grid.points[loop[0]]),
                                 length(grid.points[loop[3]] - grid.points[loop[1]]));
    double off = 0.0;
    for (const std::uint32_t k : loop) {
        off = std::max(off, std::fabs(dot(grid.points[k] - centre, n)));
    }
    if (off > kCellFlatness * size) {
        throw expected_found(
            source.at(grid.lines[loop[0]]),
            fmt::format("the corners of {} in one plane", cell_name(row, column)),
            fmt::format("them up to {:.3g} off it (more than {} of the cell's size)", off,
                        show_number(kCellFlatness)));
    }
}

// A grid point beyond the coordinate range, refused at its line (polygons placed from the grid
// are checked again where they are placed; this catches a point whose cell is skipped first).
void check_point_in_range(const SourceText& source, const PolygonGrid& grid, std::uint32_t k) {
    const Vec3& p = grid.points[k];
    if (within_coordinate_range(p)) {
        return;
    }
    throw expected_found(source.at(grid.lines[k]),
                         fmt::format("a grid point within the coordinate range {:g} to {:g}",
                                     -kMaxCoordinate, kMaxCoordinate),
                         show_point(p.x, p.y, p.z));
}

// The grid as a mesh of quads, each tagged with its texture cell (first_cell + its number).
SurfaceMesh grid_mesh(const SourceText& source, const PolygonGrid& grid, std::int32_t first_cell,
                      Diagnostics& diagnostics) {
    SurfaceMesh mesh;
    mesh.vertices = grid.points;
    mesh.polygons.reserve(static_cast<std::size_t>(grid.rows * grid.columns));
    mesh.corners.reserve(static_cast<std::size_t>(grid.rows * grid.columns * 4));
    for (std::int64_t row = 0; row < grid.rows; ++row) {
        for (std::int64_t column = 0; column < grid.columns; ++column) {
            const std::array<std::uint32_t, 4> loop = cell_loop(grid, row, column);
            const int line = grid.lines[loop[0]];
            const Vec3 newell = newell_normal(loop, mesh.vertices);
            if (const std::string_view why = degeneracy(loop, mesh.vertices, newell);
                !why.empty()) {
                // As for polygons (scene_builder.cpp): a point out of range is the real mistake,
                // as one far corner alone can make the area vanish in the rounding.
                for (const std::uint32_t k : loop) {
                    check_point_in_range(source, grid, k);
                }
                diagnostics.warn_repeated(
                    fmt::format("degenerate cells in {}", source.name),
                    fmt::format("{}: {} is degenerate ({}); skipped", source.at(line).to_string(),
                                cell_name(row, column), why));
                continue;
            }
            check_flat(source, grid, row, column, loop, newell);
            MeshPolygon p;
            p.number = static_cast<long>(row * grid.columns + column);
            p.line = line;
            p.texture_cell = first_cell + static_cast<std::int32_t>(p.number);
            mesh.add_polygon(p, {loop.begin(), loop.end()});
        }
    }
    return mesh;
}

// The object-space point at grid coordinates (u, v): bilinear in the cell that holds it, or
// extrapolated from the nearest cell for a point off the grid.
Vec3 grid_position(const PolygonGrid& grid, const GridPoint& at) {
    const auto cell = [](double x, std::int64_t cells) {
        return std::clamp(static_cast<std::int64_t>(std::floor(x)), std::int64_t{0}, cells - 1);
    };
    const std::int64_t c = cell(at.u, grid.columns);
    const std::int64_t r = cell(at.v, grid.rows);
    const double fu = at.u - static_cast<double>(c);
    const double fv = at.v - static_cast<double>(r);
    return grid.point(r, c) * ((1 - fu) * (1 - fv)) + grid.point(r, c + 1) * (fu * (1 - fv)) +
           grid.point(r + 1, c + 1) * (fu * fv) + grid.point(r + 1, c) * ((1 - fu) * fv);
}

// The cell's frame: its mean u and v edges, made perpendicular to its normal and to each other.
void set_frame(const Scene& scene, const Polygon& p, TextureCell& cell) {
    const Vec3 c0 = scene.corner_position(p, 0);
    const Vec3 c1 = scene.corner_position(p, 1);
    const Vec3 c2 = scene.corner_position(p, 2);
    const Vec3 c3 = scene.corner_position(p, 3);
    const Vec3 u = (c1 - c0) + (c2 - c3);
    const Vec3 v = (c3 - c0) + (c2 - c1);
    const Vec3 u_in_plane = u - p.normal * dot(u, p.normal);
    // A cell that passed the degeneracy check has a u edge off its normal; a crossed (bow-tie)
    // cell may not: then v alone gives the frame.
    cell.tangent_u = length(u_in_plane) > 0.0
                         ? normalize(u_in_plane)
                         : normalize(cross(v - p.normal * dot(v, p.normal), p.normal));
    const Vec3 v_in_plane =
        v - p.normal * dot(v, p.normal) - cell.tangent_u * dot(v, cell.tangent_u);
    cell.tangent_v = length(v_in_plane) > 0.0 ? normalize(v_in_plane)
                                              : normalize(cross(p.normal, cell.tangent_u));
}

// Reads a picture the texture map names (relative to the map's folder) into Scene::texture_images,
// once a file: its header first, for the check, then its pixels.
std::int32_t read_picture(Scene& scene, const SourceText& map_file, const MapPicture& picture,
                          const char* kind, TexturePictures& pictures) {
    const std::filesystem::path path =
        std::filesystem::path(map_file.name).parent_path() / picture.name;
    if (const auto known = pictures.index.find(path.lexically_normal().string());
        known != pictures.index.end()) {
        return known->second;
    }
    if (scene.texture_images.size() >=
        static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max())) {
        throw InputError(map_file.at(picture.line), "the scene has too many pictures");
    }
    Image8 image;
    try {
        const PngHeader header = read_png_header(path);
        pictures.held.push_back({picture.name, map_file.at(picture.line), header.width,
                                 header.height, header.decoded_bytes()});
        if (pictures.check) {
            pictures.check(pictures.held);
        }
        image = read_png(path);
    } catch (const IoError& e) {
        throw InputError(map_file.at(picture.line),
                         fmt::format("{} '{}': {}", kind, picture.name, e.what()));
    } catch (const InputError& e) {
        // A picture has no lines: the map's line that names it says which one is meant.
        throw InputError(map_file.at(picture.line),
                         fmt::format("{} '{}': {}", kind, picture.name, e.message()));
    }
    scene.texture_images.push_back({image.width, image.height, std::move(image.rgb), picture.name});
    const auto index = static_cast<std::int32_t>(scene.texture_images.size() - 1);
    pictures.index.emplace(path.lexically_normal().string(), index);
    return index;
}

// The grid's entry in Scene::texture_grids, with the pictures its map names.
std::uint32_t add_grid(Scene& scene, const ScnTexturedSurface& entry, const TextureMap& map,
                       const SourceText& map_file, TexturePictures& pictures) {
    TextureGrid grid;
    grid.rows = static_cast<std::uint32_t>(entry.rows);
    grid.columns = static_cast<std::uint32_t>(entry.columns);
    if (map.colour_map) {
        grid.colour_map = read_picture(scene, map_file, *map.colour_map, "colour map", pictures);
    }
    if (map.normal_map) {
        grid.normal_map = read_picture(scene, map_file, *map.normal_map, "normal map", pictures);
    }
    scene.texture_grids.push_back(grid);
    return static_cast<std::uint32_t>(scene.texture_grids.size() - 1);
}

}  // namespace

void add_textured_surface(SceneBuilder& builder, Scene& scene, const ScnTexturedSurface& entry,
                          const SourceText& grid_file, const SourceText& texture_map_file,
                          std::uint32_t file, TexturePictures& pictures, Diagnostics& diagnostics) {
    const PolygonGrid grid =
        read_grid_file(grid_file, entry.rows, entry.columns, entry.where, diagnostics);
    const TextureMap map =
        read_texture_map(texture_map_file, entry.rows, entry.columns, entry.where, diagnostics);
    const std::int64_t cells = entry.rows * entry.columns;
    if (std::ssize(scene.texture_cells) + cells > std::numeric_limits<std::int32_t>::max()) {
        throw InputError(entry.where, "the scene has too many texture-mapped cells");
    }
    const std::uint32_t grid_index = add_grid(scene, entry, map, texture_map_file, pictures);
    const auto first_cell = static_cast<std::int32_t>(scene.texture_cells.size());
    scene.texture_cells.resize(scene.texture_cells.size() + static_cast<std::size_t>(cells));
    const SurfaceMesh mesh = grid_mesh(grid_file, grid, first_cell, diagnostics);

    ScnSurface surface;
    surface.surface.file = entry.polygon_file.name;
    surface.surface.attribute_number = entry.attribute_number;
    surface.surface.texture_map = entry.texture_map.name;
    surface.surface.where = entry.where;
    surface.placement = entry.placement;
    const std::size_t first_polygon = scene.polygons.size();
    builder.add_surface(surface, mesh, file);

    const SurfacePlacement& placed = entry.placement;
    const SurfaceTransform transform(placed.scale, placed.rotation_degrees, placed.translation);
    std::vector<Vec3> centres;
    centres.reserve(map.centres.size());
    for (const GridPoint& c : map.centres) {
        centres.push_back(transform.point(grid_position(grid, c)));
    }
    const double to_world = 1.0 / std::fabs(placed.scale);  // curvatures shrink as sizes grow
    for (std::size_t id = first_polygon; id < scene.polygons.size(); ++id) {
        const Polygon& p = scene.polygons[id];
        const auto k = static_cast<std::size_t>(p.texture_cell - first_cell);
        const TextureElement& e = map.elements[k];
        TextureCell& cell = scene.texture_cells[static_cast<std::size_t>(p.texture_cell)];
        set_frame(scene, p, cell);
        double sine = 0.0;
        double cosine = 1.0;
        sin_cos_degrees(e.axis_degrees, sine, cosine);
        cell.across_axis = cell.tangent_u * -sine + cell.tangent_v * cosine;
        cell.optical_centre = centres[e.centre];
        cell.sphere = e.sphere * to_world;
        cell.cylinder = e.cylinder * to_world;
        cell.color = e.color;
        cell.grid = grid_index;
        cell.row = static_cast<std::uint32_t>(static_cast<std::int64_t>(k) / entry.columns);
        cell.column = static_cast<std::uint32_t>(static_cast<std::int64_t>(k) % entry.columns);
    }
}

}  // namespace rt
