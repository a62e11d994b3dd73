// The BVH's references: which polygons get a box, and that the boxes do not depend on how many
// threads make them.
#include "rt/accel/bvh/polygon_references.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "support/meshes/generated_meshes.h"

namespace rt::bvh {
namespace {

bool same_references(const PolygonReferences& a, const PolygonReferences& b) {
    return a.bounded.size() == b.bounded.size() && a.unbounded == b.unbounded &&
           a.scale == b.scale &&
           std::memcmp(a.bounded.data(), b.bounded.data(),
                       a.bounded.size() * sizeof(PolygonReference)) == 0;
}

// A polygon with a non-finite corner, wherever it is in the polygon, cannot be boxed: every ray
// must test it. (A NaN drops out of a minimum taken after it: a NaN between finite corners once
// left a finite box that did not even hold the first corner.)
TEST(PolygonReferences, ANonFiniteCornerAnywhereLeavesThePolygonUnbounded) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    for (const double broken : {nan, inf, -inf}) {
        for (std::uint32_t corner = 0; corner < 3; ++corner) {
            for (int axis = 0; axis < 3; ++axis) {
                Scene scene = test::make_triangle_soup(50, 3);
                const Polygon& p = scene.polygons[17];
                scene.positions[scene.corners[p.first_corner + corner]][axis] = broken;
                const PolygonReferences refs = make_polygon_references(scene, 1);
                bool bounded = false;
                for (const PolygonReference& r : refs.bounded) {
                    bounded = bounded || r.polygon == 17;
                }
                EXPECT_FALSE(bounded) << "corner " << corner << " axis " << axis << " " << broken;
                EXPECT_NE(std::find(refs.unbounded.begin(), refs.unbounded.end(), 17u),
                          refs.unbounded.end());
            }
        }
    }
}

TEST(PolygonReferences, EveryBoxHoldsItsCorners) {
    const Scene scene = test::make_tessellated_sphere(5000);
    const PolygonReferences refs = make_polygon_references(scene, 1);
    ASSERT_EQ(refs.bounded.size(), scene.polygons.size());
    for (const PolygonReference& r : refs.bounded) {
        const Polygon& p = scene.polygons[r.polygon];
        EXPECT_EQ(r.triangles, p.corner_count - 2);
        for (std::uint32_t k = 0; k < p.corner_count; ++k) {
            const Vec3 c = scene.corner_position(p, k);
            for (int axis = 0; axis < 3; ++axis) {
                EXPECT_LE(r.box.lo[axis], c[axis]);
                EXPECT_GE(r.box.hi[axis], c[axis]);
            }
        }
    }
}

// Runs of polygons on several threads, joined in order: the same references, broken polygons and
// scale as on one thread.
TEST(PolygonReferences, TheSameForAnyThreadCount) {
    Scene scene = test::make_triangle_soup(70000, 5);
    for (std::uint32_t id = 100; id < scene.polygons.size(); id += 9973) {
        scene.positions[scene.corners[scene.polygons[id].first_corner + 1]].y =
            std::numeric_limits<double>::quiet_NaN();
    }
    scene.polygons[40000].corner_count = 2;  // no fan triangle: no reference at all
    const PolygonReferences one = make_polygon_references(scene, 1);
    ASSERT_GE(one.unbounded.size(), 5u);
    for (const unsigned threads : {2u, 3u, 8u}) {
        SCOPED_TRACE(threads);
        EXPECT_TRUE(same_references(make_polygon_references(scene, threads), one));
    }
}

}  // namespace
}  // namespace rt::bvh
