#include "rt/scene/read/surface_transform.h"

#include <cmath>
#include <numbers>

namespace rt {

namespace {

struct Matrix {
    Vec3 rows[3];
    Matrix operator*(const Matrix& o) const {
        Matrix m;
        for (int i = 0; i < 3; ++i) {
            const Vec3 column{o.rows[0][i], o.rows[1][i], o.rows[2][i]};
            for (int r = 0; r < 3; ++r) {
                m.rows[r][i] = dot(rows[r], column);
            }
        }
        return m;
    }
};

// Positive angles by the right-hand rule: about x, +y turns toward +z; about y, +z toward +x;
// about z, +x toward +y.
Matrix about_x(double s, double c) {
    return {{{1, 0, 0}, {0, c, -s}, {0, s, c}}};
}
Matrix about_y(double s, double c) {
    return {{{c, 0, s}, {0, 1, 0}, {-s, 0, c}}};
}
Matrix about_z(double s, double c) {
    return {{{c, -s, 0}, {s, c, 0}, {0, 0, 1}}};
}

}  // namespace

void sin_cos_degrees(double degrees, double& sine, double& cosine) {
    const double turns = std::fmod(degrees, 360.0);
    const double quarter = turns / 90.0;
    if (quarter == std::floor(quarter)) {
        static constexpr double kSin[4] = {0, 1, 0, -1};
        const int q = (static_cast<int>(quarter) % 4 + 4) % 4;
        sine = kSin[q];
        cosine = kSin[(q + 1) % 4];
        return;
    }
    const double radians = turns * std::numbers::pi / 180.0;
    sine = std::sin(radians);
    cosine = std::cos(radians);
}

SurfaceTransform::SurfaceTransform(double scale, const Vec3& rotation_degrees,
                                   const Vec3& translation)
    : scale_(scale), translation_(translation) {
    double s[3];
    double c[3];
    for (int axis = 0; axis < 3; ++axis) {
        sin_cos_degrees(rotation_degrees[axis], s[axis], c[axis]);
    }
    const Matrix m = about_z(s[2], c[2]) * about_y(s[1], c[1]) * about_x(s[0], c[0]);
    for (int r = 0; r < 3; ++r) {
        rows_[r] = m.rows[r];
    }
}

}  // namespace rt
