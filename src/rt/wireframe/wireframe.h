// -w, "Wireframe only, no raytracing" (manual 1.2.2: "First, the outline (called a wire-frame)
// of the scene will be drawn"): the scene's lines drawn into a film through the renderer's
// camera, for the picture files now and for a window later. docs/wireframe.md has the rules.
#pragma once

#include "rt/accel/octree/octree_tree.h"
#include "rt/core/rgb.h"
#include "rt/image/film.h"
#include "rt/scene/scene.h"

namespace rt {

/// The colours of the lines, as linear intensities (1 is display level 255 at -m1).
inline constexpr Rgb kWireEdgeColour{1.0, 1.0, 1.0};
inline constexpr Rgb kWireNormalColour{0.0, 1.0, 0.0};  ///< "the little green normals"
inline constexpr Rgb kWireOctreeColour{0.25, 0.5, 1.0};

struct WireframeSettings {
    double normal_length = 0.0;          ///< the scene header's normallength; 0: none
    const OctreeTree* octree = nullptr;  ///< -oo: draw its leaves' boxes too
};

/// Draws into `film` (over what it holds): the octree's boxes first, then every polygon's edges,
/// then the normals, each line clipped to the screen (the near plane) and the view area, and
/// only its pixels inside the film's window set. The film's view must be the scene's.
/// Marks every row of the window finished.
void draw_wireframe(const Scene& scene, const WireframeSettings& settings, Film& film);

}  // namespace rt
