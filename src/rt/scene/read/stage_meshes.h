// The stage `rt --model` sets a model on (model_scene.h): a checkerboard floor and a square light,
// made as optical surface meshes so that the scene builder places them like any file's.
#pragma once

#include "rt/scene/read/surface_mesh.h"

namespace rt {

/// An n x n checkerboard in the plane y = 0, from -half to +half in x and z, facing +y; its
/// squares' attribute offsets alternate 0 and 1, as the manual's checker8 does.
SurfaceMesh checkerboard_mesh(int n, double half);

/// A square in the plane y = 0, from -half to +half in x and z, facing -y (down), offset 0: the
/// manual's square light.
SurfaceMesh square_light_mesh(double half);

}  // namespace rt
