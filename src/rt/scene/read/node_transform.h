// The transform a model's node hierarchy gives its meshes (glTF places meshes by nodes), composed
// in double precision: points, normals (by the inverse transpose), and whether it mirrors.
#pragma once

#include <array>

#include "rt/core/vec3.h"

namespace rt {

class NodeTransform {
public:
    /// The top three rows of a 4x4 affine matrix, row-major: x' = m[0][0] x + ... + m[0][3].
    using Matrix3x4 = std::array<std::array<double, 4>, 3>;

    /// The identity.
    NodeTransform() = default;
    /// This transform after the child's own: parent * local.
    NodeTransform then(const Matrix3x4& local) const;

    Vec3 point(const Vec3& p) const;
    /// A normal carried by the transform and normalised; zero if nothing is left of it (a
    /// singular transform flattens some surfaces to lines).
    Vec3 direction(const Vec3& n) const;
    /// The determinant is negative: the transform mirrors, so loops turn the other way round.
    bool mirrors() const { return mirrors_; }

private:
    Matrix3x4 m_{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}};
    /// The cofactors of the 3x3 part, with the determinant's sign: the inverse transpose times
    /// |det|, which only normalising follows.
    std::array<std::array<double, 3>, 3> normal_{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    bool mirrors_ = false;
};

}  // namespace rt
