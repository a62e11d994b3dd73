#include "rt/scene/read/model_scene.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "rt/scene/read/model_reader.h"
#include "rt/scene/read/scene_builder.h"
#include "rt/scene/read/stage_meshes.h"

namespace rt {

namespace {

constexpr int kCheckers = 8;

// From the model towards the eye: in front (+z, the side glTF calls the front), a little to the
// side and above.
Vec3 view_direction() {
    return normalize(Vec3{-0.4, 0.45, 1.0});
}

Attribute matte(Rgb color, long index) {
    Attribute a;
    a.color = color;
    a.ambient = 0.15;
    a.diffuse = 0.85;
    a.reflect_cone_degrees = 60;
    a.reflect_cone_exponent = 4;
    a.refract_cone_degrees = 60;
    a.refract_cone_exponent = 4;
    a.index = index;
    return a;
}

// One attribute per material of the model, in its colour (light grey where it gives none), with a
// highlight and a faint mirror reflection; then the floor's two and the light's.
std::vector<Attribute> stage_attributes(const SurfaceMesh& model) {
    std::vector<Attribute> attributes;
    const std::size_t materials = std::max<std::size_t>(1, model.materials.size());
    for (std::size_t k = 0; k < materials; ++k) {
        Rgb color{0.85, 0.85, 0.85};
        if (k < model.materials.size() && model.materials[k].diffuse) {
            const Rgb& d = *model.materials[k].diffuse;
            color = {std::clamp(d.r, 0.0, 1.0), std::clamp(d.g, 0.0, 1.0),
                     std::clamp(d.b, 0.0, 1.0)};
        }
        Attribute a = matte(color, static_cast<long>(k));
        a.specular_exponent = 20;
        a.diffuse = 0.65;
        a.specular = 0.2;
        a.reflect_cone_degrees = 0;  // a sharp reflection: no noise at one sample a pixel
        attributes.push_back(a);
    }
    const auto next = static_cast<long>(attributes.size());
    attributes.push_back(matte({0.8, 0.8, 0.78}, next));
    attributes.push_back(matte({0.25, 0.3, 0.4}, next + 1));
    Attribute light = matte({1, 1, 1}, next + 2);
    light.ambient = 0;
    light.diffuse = 0;
    light.emission = 1;
    attributes.push_back(light);
    return attributes;
}

// The box around the corners the model's polygons use.
Box3 model_bounds(const SurfaceMesh& mesh) {
    Box3 box;
    for (const std::uint32_t v : mesh.corners) {
        box.add(mesh.vertices[v]);
    }
    return box;
}

ScnSurface stage_surface(const std::string& file, long attribute, double scale,
                         const Vec3& translation) {
    ScnSurface s;
    s.surface.file = file;
    s.surface.entity = 1;
    s.surface.attribute_number = attribute;
    s.surface.where = {file, 0, 0};
    s.placement.scale = scale;
    s.placement.translation = translation;
    return s;
}

// The eye looks at the model's centre from view_direction(), far enough for the sphere around the
// model to fit the narrower view angle with a margin.
SceneView framing_view(const Box3& placed) {
    SceneView view;
    view.width = 512;
    view.height = 400;
    view.view_angle_x_degrees = 32;
    view.view_angle_y_degrees = 25;
    view.window = {0, 0, view.width - 1, view.height - 1};
    const double radius = 0.5 * length(placed.extent());
    const double half_angle = 0.5 * std::min(view.view_angle_x_degrees, view.view_angle_y_degrees) *
                              std::numbers::pi / 180.0;
    const double distance = 1.1 * radius / std::sin(half_angle);
    view.look = placed.centre();
    view.eye = view.look + view_direction() * distance;
    view.screen_distance = 0.5 * (distance - radius);  // in front of everything in view
    return view;
}

}  // namespace

Scene model_scene(const std::filesystem::path& model, const ReaderDialect& dialect,
                  Diagnostics& diagnostics) {
    const SourceLocation named_at{"--model", 0, 0};
    const SurfaceMesh mesh = read_model_file(model, model.string(), named_at, diagnostics);
    Scene scene;
    scene.scene_file = model;
    scene.header = {.center = 0,
                    .lghtick = 2,
                    .sptncde = 0,
                    .octr = 0,
                    .graphmode = 0,
                    .normallength = 1.0,
                    .maxdepth = 2,
                    .maxdist = 1.0};
    scene.attributes = stage_attributes(mesh);
    scene.source_files = {model.string(), "(the floor of --model)", "(the light of --model)"};

    // Scaled to kModelSize, standing on y = 0 (a hair above the floor), centred over the origin.
    const Box3 bounds = model_bounds(mesh);
    const double scale = kModelSize / std::max(bounds.largest_extent(), 1e-300);
    const Vec3 centre = bounds.centre();
    ScnSurface model_entry =
        stage_surface(model.string(), 0, scale,
                      {-scale * centre.x, 0.01 - scale * bounds.lo.y, -scale * centre.z});
    model_entry.surface.filetype = kModelFiletype;
    model_entry.surface.smooth_shaded = dialect.smooth_shade_field;
    const Box3 placed{bounds.lo * scale + model_entry.placement.translation,
                      bounds.hi * scale + model_entry.placement.translation};

    const auto floor_attribute = static_cast<long>(scene.attributes.size() - 3);
    const double footprint = std::max(placed.extent().x, placed.extent().z);
    const double floor_half = std::max(1.2 * footprint, 0.6 * kModelSize);
    const double height = placed.hi.y;
    const ScnSurface floor = stage_surface(scene.source_files[1], floor_attribute, 1.0, {});
    const ScnSurface light = stage_surface(scene.source_files[2], floor_attribute + 2, 1.0,
                                           {0.3 * floor_half, height + 12, 0.3 * floor_half});
    scene.view = framing_view(placed);

    SceneBuilder builder(scene, diagnostics);
    const SurfaceMesh floor_mesh = checkerboard_mesh(kCheckers, floor_half);
    const SurfaceMesh light_mesh = square_light_mesh(3.0);
    // Added after the model, the floor copied a million-polygon model's arrays once more.
    builder.reserve_for({&mesh, &floor_mesh, &light_mesh});
    builder.add_surface(model_entry, mesh, 0);
    diagnostics.finish_repeats();
    if (scene.polygons.empty()) {  // each was degenerate, and skipped with a warning
        throw InputError({model.string(), 0, 0},
                         "the model holds no polygons that are not "
                         "degenerate: there is nothing to render");
    }
    builder.add_surface(floor, floor_mesh, 1);
    builder.add_surface(light, light_mesh, 2);
    builder.finish(named_at);
    return scene;
}

}  // namespace rt
