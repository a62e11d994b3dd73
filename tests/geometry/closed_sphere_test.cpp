// Watertightness on closed UV spheres (quads and triangles, poles shared by a ring of triangles)
// at coordinates that round: every line meets them 0 or 2 times, exactly twice through the
// inside, including lines through every corner and edge middle and along every edge.
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/line_hits.h"
#include "support/scene_builder.h"

namespace rt::test {
namespace {

struct SphereMesh {
    int stacks;
    int slices;
    bool triangles;
};

class ClosedSphere : public ::testing::TestWithParam<SphereMesh> {
protected:
    const Vec3 centre_{0.1, -0.2, 0.3};  // not dyadic: projections round
    const double radius_ = 1.7;
    Scene sphere_ =
        make_sphere(centre_, radius_, GetParam().stacks, GetParam().slices, GetParam().triangles);
};

TEST_P(ClosedSphere, LoopsAreConsistent) {
    expect_consistent_loops(sphere_);
}

TEST_P(ClosedSphere, RandomLinesThroughTheMiddle) {
    std::mt19937_64 random(21);
    // Within 0.35 radius of the centre: inside even the coarsest mesh, the 2x3 bipyramid.
    std::uniform_real_distribution<double> offset(-0.2, 0.2);
    for (int i = 0; i < 1500; ++i) {
        const Vec3 inside =
            centre_ + Vec3{offset(random), offset(random), offset(random)} * radius_;
        const Vec3 direction = random_unit(random);
        expect_two_crossings(sphere_, {inside - direction * 5.0, direction});
    }
}

TEST_P(ClosedSphere, LinesThroughEveryCornerAndEdgeMiddle) {
    std::mt19937_64 random(22);
    for (const Polygon& p : sphere_.polygons) {
        for (std::uint32_t k = 0; k < p.corner_count; ++k) {
            const Vec3 a = sphere_.corner_position(p, k);
            const Vec3 b = sphere_.corner_position(p, (k + 1) % p.corner_count);
            for (const Vec3& through : {a, (a + b) * 0.5}) {
                // Toward the centre: through the inside.
                expect_two_crossings(sphere_, {through + (through - centre_), centre_ - through});
                // Any direction at all: grazing, tangent, along edges.
                expect_even_crossing(sphere_, {through, random_unit(random)});
            }
            expect_even_crossing(sphere_, {a, b - a});  // along the edge itself
        }
    }
}

TEST_P(ClosedSphere, AxisParallelLinesThroughThePoles) {
    // The poles are corners shared by a whole ring of triangles.
    const Vec3 north = centre_ + Vec3{0, radius_, 0};
    expect_two_crossings(sphere_, {north + Vec3{0, 3, 0}, {0, -1, 0}});
    std::mt19937_64 random(23);
    std::uniform_real_distribution<double> coordinate(-2.0, 2.0);
    for (int i = 0; i < 1500; ++i) {
        const Vec3 origin =
            centre_ + Vec3{coordinate(random), coordinate(random), coordinate(random)};
        for (const Vec3& axis : {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}}) {
            expect_even_crossing(sphere_, {origin, axis});
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Meshes, ClosedSphere,
                         ::testing::Values(SphereMesh{2, 3, false}, SphereMesh{8, 12, false},
                                           SphereMesh{8, 12, true}, SphereMesh{16, 24, true}),
                         [](const ::testing::TestParamInfo<SphereMesh>& param) {
                             return std::to_string(param.param.stacks) + "x" +
                                    std::to_string(param.param.slices) +
                                    (param.param.triangles ? "Triangles" : "Quads");
                         });

}  // namespace
}  // namespace rt::test
