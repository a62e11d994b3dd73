#include "rt/wireframe/wireframe.h"

#include <optional>
#include <vector>

#include "rt/wireframe/line_projection.h"
#include "rt/wireframe/line_raster.h"
#include "rt/wireframe/wire_segments.h"

namespace rt {

namespace {

void draw_all(const std::vector<WireSegment>& lines, const LineProjection& projection,
              const Rgb& colour, Film& film) {
    for (const WireSegment& line : lines) {
        if (const std::optional<PixelSegment> s = projection.segment(line.from, line.to)) {
            draw_line(film, *s, colour);
        }
    }
}

}  // namespace

void draw_wireframe(const Scene& scene, const WireframeSettings& settings, Film& film) {
    const LineProjection projection(scene.view.camera());
    if (settings.octree != nullptr) {
        draw_all(octree_leaf_edges(*settings.octree), projection, kWireOctreeColour, film);
    }
    draw_all(polygon_edges(scene), projection, kWireEdgeColour, film);
    draw_all(polygon_normals(scene, settings.normal_length), projection, kWireNormalColour, film);
    film.set_first_finished_row(film.window().top);
}

}  // namespace rt
