#include "rt/scene/read/node_transform.h"

#include <cmath>

namespace rt {

NodeTransform NodeTransform::then(const Matrix3x4& local) const {
    NodeTransform out;
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 4; ++c) {
            out.m_[r][c] = m_[r][0] * local[0][c] + m_[r][1] * local[1][c] +
                           m_[r][2] * local[2][c] + (c == 3 ? m_[r][3] : 0.0);
        }
    }
    const Matrix3x4& a = out.m_;
    const double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
                       a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                       a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    out.mirrors_ = det < 0;
    const double sign = det < 0 ? -1.0 : 1.0;
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) {
            // Cyclic indices give each cofactor its sign.
            const int r1 = (r + 1) % 3;
            const int r2 = (r + 2) % 3;
            const int c1 = (c + 1) % 3;
            const int c2 = (c + 2) % 3;
            out.normal_[r][c] = sign * (a[r1][c1] * a[r2][c2] - a[r1][c2] * a[r2][c1]);
        }
    }
    return out;
}

Vec3 NodeTransform::point(const Vec3& p) const {
    return {m_[0][0] * p.x + m_[0][1] * p.y + m_[0][2] * p.z + m_[0][3],
            m_[1][0] * p.x + m_[1][1] * p.y + m_[1][2] * p.z + m_[1][3],
            m_[2][0] * p.x + m_[2][1] * p.y + m_[2][2] * p.z + m_[2][3]};
}

Vec3 NodeTransform::direction(const Vec3& n) const {
    const Vec3 v{normal_[0][0] * n.x + normal_[0][1] * n.y + normal_[0][2] * n.z,
                 normal_[1][0] * n.x + normal_[1][1] * n.y + normal_[1][2] * n.z,
                 normal_[2][0] * n.x + normal_[2][1] * n.y + normal_[2][2] * n.z};
    const double l = length(v);
    return l > 0 && std::isfinite(l) ? v / l : Vec3{};
}

}  // namespace rt
