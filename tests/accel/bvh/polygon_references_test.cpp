// The BVH's references: which polygons get a box, and that the boxes do not depend on how many
// threads make them.
#include "rt/accel/bvh/polygon_references.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "rt/accel/float_prefilter/float_ray.h"

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

// Each box is the documented one, bit for bit, worked out here one coordinate at a time: the
// corners' box, widened by (deviation + 2^-48 size) 2^21 for corners off the polygon's plane,
// rounded outward to float; no box when that is not finite. The values are chosen to be hard:
// signed zeros, subnormals, doubles between floats, sizes beyond float's range, normals that are
// not the corners' (so the widening is not zero).
TEST(PolygonReferences, TrianglesGetTheDocumentedBoxBitForBit) {
    std::mt19937_64 random(11);
    const std::vector<double> hard = {
        0.0,    -0.0,    1e-310, -1e-310, 1.0 + 0x1p-30, -3.0 - 0x1p-29, 0x1p-149,
        3.4e38, -3.4e38, 1e39,   0.1,     -0.7,          1e-30,          123456.789};
    std::uniform_int_distribution<std::size_t> pick(0, hard.size() - 1);
    std::uniform_real_distribution<double> spread(-10.0, 10.0);
    std::bernoulli_distribution use_hard(0.3);
    const auto value = [&] { return use_hard(random) ? hard[pick(random)] : spread(random); };
    Scene scene;
    const std::uint32_t count = 4000;
    for (std::uint32_t id = 0; id < count; ++id) {
        Polygon p;
        p.first_corner = static_cast<std::uint32_t>(scene.corners.size());
        p.corner_count = 3;
        p.normal = id % 3 == 0 ? Vec3{0, 0, 1} : Vec3{value(), value(), value()};
        // Every tenth of signed zeros alone: no widening, so the zeros' signs reach the box.
        const bool zeros = id % 10 == 0;
        const auto coordinate = [&] { return zeros ? (random() % 2 == 0 ? 0.0 : -0.0) : value(); };
        for (int k = 0; k < 3; ++k) {
            scene.corners.push_back(static_cast<std::uint32_t>(scene.positions.size()));
            scene.positions.push_back({coordinate(), coordinate(), coordinate()});
        }
        scene.polygons.push_back(p);
    }
    const PolygonReferences refs = make_polygon_references(scene, 1);
    std::size_t bounded = 0;
    std::vector<std::uint32_t> unbounded;
    for (std::uint32_t id = 0; id < count; ++id) {
        SCOPED_TRACE(id);
        const Polygon& p = scene.polygons[id];
        const Vec3 a = scene.corner_position(p, 0);
        bool finite = is_finite(p.normal);
        double deviation = 0.0;
        double size = 0.0;
        Vec3 lo = a;
        Vec3 hi = a;
        for (std::uint32_t k = 0; k < 3; ++k) {
            const Vec3 c = scene.corner_position(p, k);
            finite = finite && is_finite(c);
            // As written, a < b ? a : b: with signed zeros, the order decides the sign.
            lo = min_components(lo, c);
            hi = max_components(hi, c);
            for (int axis = 0; axis < 3; ++axis) {
                size = std::max(size, std::fabs(c[axis]));
            }
            const Vec3 d = c - a;
            deviation = std::max(deviation,
                                 std::fabs(p.normal.x * d.x + p.normal.y * d.y + p.normal.z * d.z));
        }
        const double widen = (deviation + 0x1p-48 * size) * 0x1p21;
        PolygonReference expected;
        double float_size = 0.0;
        for (int axis = 0; axis < 3; ++axis) {
            finite = finite && std::isfinite(lo[axis] - widen) && std::isfinite(hi[axis] + widen) &&
                     std::isfinite(deviation);
            expected.box.lo[axis] = float_below(lo[axis] - widen);
            expected.box.hi[axis] = float_above(hi[axis] + widen);
            float_size = std::max({float_size, std::fabs(double{expected.box.lo[axis]}),
                                   std::fabs(double{expected.box.hi[axis]})});
        }
        if (!finite || !std::isfinite(float_size)) {
            unbounded.push_back(id);
            continue;
        }
        ASSERT_LT(bounded, refs.bounded.size());
        const PolygonReference& got = refs.bounded[bounded++];
        ASSERT_EQ(got.polygon, id);
        EXPECT_EQ(got.triangles, 1u);
        for (int axis = 0; axis < 3; ++axis) {  // bit for bit: the sign of a zero counts
            EXPECT_EQ(std::bit_cast<std::uint32_t>(got.box.lo[axis]),
                      std::bit_cast<std::uint32_t>(expected.box.lo[axis]))
                << "lo " << axis << ": " << got.box.lo[axis] << " " << expected.box.lo[axis];
            EXPECT_EQ(std::bit_cast<std::uint32_t>(got.box.hi[axis]),
                      std::bit_cast<std::uint32_t>(expected.box.hi[axis]))
                << "hi " << axis << ": " << got.box.hi[axis] << " " << expected.box.hi[axis];
        }
    }
    EXPECT_EQ(bounded, refs.bounded.size());
    EXPECT_EQ(refs.unbounded, unbounded);
    EXPECT_GT(bounded, count / 4);
    EXPECT_GT(unbounded.size(), 10u);
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
