// Watertightness on a closed box of shared corners, as 6 quads and as 12 triangles: every line
// meets it 0 or 2 times and exactly twice through the inside, including lines exactly through
// its corners, edge middles and face centres (dyadic inputs: exact projections), along its edges,
// in the planes of its faces and nearly parallel to them.
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "support/line_hits.h"
#include "support/scene_builder.h"

namespace rt::test {
namespace {

class ClosedBox : public ::testing::TestWithParam<bool> {
protected:
    const Vec3 lo_{-1, -2, -0.5};
    const Vec3 hi_{3, 1, 2.5};
    Scene box_ = make_box(lo_, hi_, GetParam());
    Vec3 centre() const { return (lo_ + hi_) * 0.5; }
};

TEST_P(ClosedBox, LoopsAreConsistent) {
    expect_consistent_loops(box_);
}

TEST_P(ClosedBox, RandomLinesThroughTheInside) {
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < 3000; ++i) {
        const Vec3 inside{lo_.x + (hi_.x - lo_.x) * unit(random),
                          lo_.y + (hi_.y - lo_.y) * unit(random),
                          lo_.z + (hi_.z - lo_.z) * unit(random)};
        const Vec3 direction = random_unit(random);
        expect_two_crossings(box_, {inside - direction * 20.0, direction});
    }
}

TEST_P(ClosedBox, RandomLinesAnywhere) {
    std::mt19937_64 random(12);
    std::uniform_real_distribution<double> coordinate(-4.0, 4.0);
    for (int i = 0; i < 3000; ++i) {
        const Vec3 origin{coordinate(random), coordinate(random), coordinate(random)};
        expect_even_crossing(box_, {origin, random_unit(random)});
    }
}

TEST_P(ClosedBox, LinesExactlyThroughEveryCorner) {
    for (const Vec3& corner : box_corners(lo_, hi_)) {
        for (const Vec3& direction : dyadic_directions()) {
            const Ray ray = ray_through(corner, direction);
            expect_even_crossing(box_, ray);
            // Pointing strictly into the box (every component toward the centre): the inside.
            const Vec3 inward = centre() - corner;
            if (direction.x * inward.x > 0 && direction.y * inward.y > 0 &&
                direction.z * inward.z > 0) {
                expect_two_crossings(box_, ray);
            }
        }
    }
}

TEST_P(ClosedBox, LinesExactlyThroughEdgeMiddlesAndFaceCentres) {
    const std::vector<Vec3> corners = box_corners(lo_, hi_);
    std::vector<Vec3> points;
    for (std::size_t a = 0; a < corners.size(); ++a) {
        for (std::size_t b = a + 1; b < corners.size(); ++b) {
            points.push_back((corners[a] + corners[b]) * 0.5);  // edges, face diagonals, centre
        }
    }
    for (const Vec3& p : points) {
        for (const Vec3& direction : dyadic_directions()) {
            const Ray ray = ray_through(p, direction);
            expect_even_crossing(box_, ray);
            if ((p - centre()) == Vec3{}) {
                expect_two_crossings(box_, ray);
            }
        }
    }
}

TEST_P(ClosedBox, LinesAlongEdgesAndInFacePlanes) {
    // Axis-parallel lines on the grid of the box's own coordinates: along its 12 edges, in the
    // planes of its faces, through the middles of faces.
    const double xs[] = {lo_.x, 1.0, hi_.x};
    const double ys[] = {lo_.y, -0.5, hi_.y};
    const double zs[] = {lo_.z, 1.0, hi_.z};
    for (const double x : xs) {
        for (const double y : ys) {
            expect_even_crossing(box_, {{x, y, -10}, {0, 0, 1}});
            expect_even_crossing(box_, {{x, y, 10}, {0, 0, -1}});
        }
        for (const double z : zs) {
            expect_even_crossing(box_, {{x, -10, z}, {0, 1, 0}});
        }
    }
    for (const double y : ys) {
        for (const double z : zs) {
            expect_even_crossing(box_, {{-10, y, z}, {1, 0, 0}});
        }
    }
    expect_two_crossings(box_, {{1.0, -0.5, -10}, {0, 0, 1}});
}

TEST_P(ClosedBox, NearlyParallelToFaces) {
    std::mt19937_64 random(13);
    std::uniform_real_distribution<double> tilt(-1e-12, 1e-12);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < 2000; ++i) {
        // Through a point of a face plane (z = lo.z), almost along it.
        const Vec3 on_face{lo_.x + (hi_.x - lo_.x) * unit(random),
                           lo_.y + (hi_.y - lo_.y) * unit(random), lo_.z};
        const Vec3 direction{1.0, tilt(random), tilt(random)};
        expect_even_crossing(box_, {on_face - direction * 10.0, direction});
        // Just inside: must get through.
        const Vec3 inside = on_face + Vec3{0, 0, 1e-3};
        expect_two_crossings(box_, {inside - direction * 10.0, direction});
    }
}

INSTANTIATE_TEST_SUITE_P(QuadsAndTriangles, ClosedBox, ::testing::Bool(),
                         [](const ::testing::TestParamInfo<bool>& param) {
                             return param.param ? "Triangles" : "Quads";
                         });

}  // namespace
}  // namespace rt::test
