// -doi's session driven by scripts on string streams: each answer checked against the tree, the
// DDDA's own walk and brute force, and bad commands answered without ending the session.
#include "rt/accel/octree/octree_session.h"

#include <cmath>
#include <cstdint>
#include <optional>
#include <regex>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "rt/accel/brute_force.h"
#include "rt/accel/octree/octree_ddda.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "support/scene_builder.h"
#include "support/temp_dir.h"

namespace rt::test {
namespace {

// A UV sphere: enough polygons that the octree splits several levels down.
struct Fixture {
    Scene scene = make_sphere({0.1, 0.2, 0.3}, 2.0, 8, 12, false);
    Octree octree{scene, [] {
                      AccelSettings s;
                      s.kind = AccelKind::Octree;
                      s.octree.depth = 3;
                      return s;
                  }()};
    int failed = 0;

    Fixture() {
        scene.view.width = 32;
        scene.view.height = 24;
        scene.view.window = {0, 0, 31, 23};
        scene.view.eye = {1.0, 2.0, -9.0};
        scene.view.look = {0.1, 0.2, 0.3};
    }

    // The answers to a script, without the two banner lines.
    std::vector<std::string> answers(const std::string& script, const std::string& prompt = "") {
        std::istringstream in(script);
        std::ostringstream out;
        failed = run_octree_session(scene, octree, {in, out, prompt});
        std::vector<std::string> lines = lines_of(out.str());
        EXPECT_GE(lines.size(), 2U);
        EXPECT_EQ(lines[0].rfind("octree: depth 3, ", 0), 0U) << lines[0];
        lines.erase(lines.begin(), lines.begin() + 2);
        return lines;
    }
};

// The node a line names: "node 12, ...".
int node_of(const std::string& line) {
    std::smatch m;
    if (!std::regex_search(line, m, std::regex(R"(node (\d+),)"))) {
        return -1;
    }
    return std::stoi(m[1]);
}

TEST(OctreeSession, HelpListsEveryCommand) {
    Fixture f;
    const std::vector<std::string> lines = f.answers("help\n");
    std::string text;
    for (const std::string& l : lines) {
        text += l + "\n";
    }
    for (const char* command : {"help", "node", "child N", "up", "root", "list", "find X Y Z",
                                "ray OX OY OZ DX DY DZ", "pixel X Y", "quit"}) {
        EXPECT_NE(text.find(std::string("  ") + command + " "), std::string::npos) << command;
    }
    EXPECT_EQ(f.failed, 0);
}

TEST(OctreeSession, WalksDownAndBackUpTheTree) {
    Fixture f;
    const OctreeTree& tree = f.octree.tree();
    ASSERT_FALSE(tree.nodes[0].is_leaf());
    const std::vector<std::string> lines = f.answers("node\nchild 5\nup\nchild 0\nroot\n");
    ASSERT_EQ(lines.size(), 5U);
    EXPECT_EQ(lines[0].rfind("node 0, the root (level 0): lattice (0, 0, 0) side 8, box ", 0), 0U)
        << lines[0];
    EXPECT_NE(lines[0].find(fmt::format("interior, children {} to {}", tree.nodes[0].first,
                                        tree.nodes[0].first + 7)),
              std::string::npos);
    // Octant 5 is +x and +z: the lattice corner (4, 0, 4), half the side.
    EXPECT_EQ(node_of(lines[1]), static_cast<int>(tree.nodes[0].first + 5));
    EXPECT_NE(lines[1].find("path 5 (level 1): lattice (4, 0, 4) side 4"), std::string::npos)
        << lines[1];
    EXPECT_EQ(node_of(lines[2]), 0);
    EXPECT_EQ(node_of(lines[3]), static_cast<int>(tree.nodes[0].first));
    EXPECT_EQ(node_of(lines[4]), 0);
    EXPECT_EQ(f.failed, 0);
}

TEST(OctreeSession, FindGoesToTheLeafTheDddaReads) {
    Fixture f;
    const OctreeTree& tree = f.octree.tree();
    for (const Vec3& p : {Vec3{0.1, 0.2, 0.3}, Vec3{1.9, 0.25, 0.3}, Vec3{-1.2, 1.5, -0.4}}) {
        const std::vector<std::string> lines =
            f.answers(fmt::format("find {} {} {}\nlist\n", p.x, p.y, p.z));
        ASSERT_GE(lines.size(), 3U);
        // The leaf the DDDA's cursor finds for the lattice cell holding p.
        std::int64_t cell[3];
        for (int a = 0; a < 3; ++a) {
            cell[a] =
                static_cast<std::int64_t>(std::floor((p[a] - tree.world.lo[a]) / tree.step[a]));
        }
        const OctreeCursor cursor(tree, cell);
        const int expected = static_cast<int>(cursor.leaf_node() - tree.nodes.data());
        EXPECT_EQ(lines[0], fmt::format("({:.6g}, {:.6g}, {:.6g}) is in lattice cell ({}, {}, {})",
                                        p.x, p.y, p.z, cell[0], cell[1], cell[2]));
        EXPECT_EQ(node_of(lines[1]), expected) << lines[1];
        EXPECT_NE(lines[1].find("; leaf, "), std::string::npos);
        // list: the node again, then one line per polygon of the leaf, in the leaf's order.
        EXPECT_EQ(node_of(lines[2]), expected);
        std::vector<std::string> listed(lines.begin() + 3, lines.end());
        const std::span<const std::uint32_t> ids = tree.leaf_polygons(*cursor.leaf_node());
        ASSERT_EQ(listed.size(), ids.size());
        for (std::size_t i = 0; i < ids.size(); ++i) {
            EXPECT_EQ(listed[i].rfind(fmt::format("  polygon {} from ", ids[i]), 0), 0U)
                << listed[i];
        }
    }
    EXPECT_EQ(f.answers("find 50 0 0\n")[0].rfind("error: find: (50, 0, 0) is outside", 0), 0U);
}

TEST(OctreeSession, ARayIsWalkedLeafByLeafToBruteForcesHit) {
    Fixture f;
    const OctreeTree& tree = f.octree.tree();
    const Ray ray{{-5.0, 0.7, -4.0}, {1.0, -0.05, 0.8}};
    const std::vector<std::string> lines =
        f.answers(fmt::format("ray {} {} {} {} {} {}\n", ray.origin.x, ray.origin.y, ray.origin.z,
                              ray.direction.x, ray.direction.y, ray.direction.z));
    ASSERT_GE(lines.size(), 4U);
    EXPECT_EQ(lines[0], "ray from (-5, 0.7, -4) along (1, -0.05, 0.8)");
    EXPECT_EQ(lines[1].rfind("enters the world at t ", 0), 0U);
    // The steps are the leaves walk_octree visits, in its order.
    std::vector<int> expected;
    walk_octree(tree, ray, Interval{}, [&](auto, double, const OctreeLeafAt& leaf) {
        expected.push_back(static_cast<int>(leaf.node - tree.nodes.data()));
        return false;
    });
    std::vector<int> steps;
    for (std::size_t i = 2; i + 1 < lines.size(); ++i) {
        EXPECT_EQ(lines[i].rfind(fmt::format("step {}: ", steps.size() + 1), 0), 0U) << lines[i];
        steps.push_back(node_of(lines[i]));
    }
    EXPECT_EQ(steps, expected);
    EXPECT_NE(lines[lines.size() - 2].find("out of the world"), std::string::npos);
    // The hit is brute force's.
    const BruteForce brute(f.scene);
    TraceCounters counters;
    const std::optional<Hit> hit = brute.closest_hit(ray, Interval{}, counters);
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(lines.back().rfind(fmt::format("hit: polygon {} from ", hit->polygon), 0), 0U)
        << lines.back();
    // A ray that misses the world.
    const std::vector<std::string> miss = f.answers("ray 20 20 20 1 0 0\n");
    EXPECT_EQ(miss.back(), "misses the octree's world");
}

TEST(OctreeSession, APixelIsTheEyeRayThroughItsCentre) {
    Fixture f;
    const Ray eye = f.scene.view.camera().primary_ray(16.5, 12.5);
    const std::vector<std::string> by_pixel = f.answers("pixel 16 12\n");
    const std::vector<std::string> by_ray =
        f.answers(fmt::format("ray {} {} {} {} {} {}\n", eye.origin.x, eye.origin.y, eye.origin.z,
                              eye.direction.x, eye.direction.y, eye.direction.z));
    EXPECT_EQ(by_pixel, by_ray);
    EXPECT_EQ(by_pixel.back().rfind("hit: polygon ", 0), 0U) << by_pixel.back();
}

TEST(OctreeSession, BadCommandsAreAnsweredAndTheSessionGoesOn) {
    Fixture f;
    const std::vector<std::string> lines = f.answers(
        "frobnicate\nchild 9\nchild\nup\nfind 1 x 2\nray 0 0 0 0 0 0\npixel 32 0\n"
        "# a comment\n\n   node   \n");
    const std::vector<std::string> expected = {
        "error: unknown command 'frobnicate'; 'help' lists the commands",
        "error: child: expected an octant from 0 to 7, found '9'",
        "error: child: expected 1 argument (N), found 0",
        "error: up: already at the root",
        "error: find: expected a number, found 'x'",
        "error: ray: the direction must not be zero",
        "error: pixel: expected a column from 0 to 31 and a row from 0 to 23, found '32' '0'",
    };
    ASSERT_EQ(lines.size(), expected.size() + 1);
    for (std::size_t i = 0; i < expected.size(); ++i) {
        EXPECT_EQ(lines[i], expected[i]);
    }
    EXPECT_EQ(node_of(lines.back()), 0);  // the session went on
    EXPECT_EQ(f.failed, 7);
}

TEST(OctreeSession, QuitEndsItAndSoDoesTheEndOfTheInput) {
    Fixture f;
    EXPECT_EQ(f.answers("node\nquit\nnode\n").size(), 1U);
    EXPECT_EQ(f.answers("node").size(), 1U);  // a last line without its newline still counts
    EXPECT_EQ(f.answers("").size(), 0U);
    // A prompt before every command, and a newline after the last one left open.
    std::istringstream in("node\n");
    std::ostringstream out;
    run_octree_session(f.scene, f.octree, {in, out, "octree> "});
    const std::vector<std::string> lines = lines_of(out.str());
    ASSERT_EQ(lines.size(), 4U);
    EXPECT_EQ(lines[2].rfind("octree> node 0, the root", 0), 0U) << lines[2];
    EXPECT_EQ(lines[3], "octree> ");
}

}  // namespace
}  // namespace rt::test
