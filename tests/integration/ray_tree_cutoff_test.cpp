// The ray tree's growth: the warning with its bound on rays per sample, and --cutoff, which
// stops branches whose weight falls below it. Rays are counted from -p's table, never timed.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "rt/image/gro_format.h"

#include <gtest/gtest.h>

#include "nested_glass.h"
#include "support/run_program.h"
#include "support/temp_dir.h"

namespace rt::test {
namespace {

ProgramResult render(const TempDir& dir, std::vector<std::string> switches) {
    switches.insert(switches.begin(), {"glass", "-n", "-p", "--no-window", "--quiet"});
    return run_program("rt", switches, dir.path());
}

// Depth 12 without a cutoff traces about 380,000 rays on 32 x 24 pixels; at depth 40 the full
// tree would need some 2e12 per sample, yet the cutoff finishes it with fewer than at depth 12.
TEST(RayTreeCutoff, FinishesADeepDoublingTreeWithFarFewerRays) {
    const TempDir shallow;
    write_nested_glass(shallow, "glass", 12);
    const ProgramResult full = render(shallow, {});
    ASSERT_EQ(full.exit_code, 0) << full.err;
    EXPECT_EQ(full.err.find("rays per sample"), std::string::npos) << full.err;  // 8e3: no warning

    const TempDir deep;
    write_nested_glass(deep, "glass", 40);
    const ProgramResult cut = render(deep, {"--cutoff", "0.01"});
    ASSERT_EQ(cut.exit_code, 0) << cut.err;
    EXPECT_EQ(cut.err.find("warning"), std::string::npos) << cut.err;  // the tree is bounded
    EXPECT_LT(rays_traced(cut.out) * 10, rays_traced(full.out)) << cut.out << full.out;
}

TEST(RayTreeCutoff, CutoffZeroLeavesThePictureAsItIs) {
    const TempDir dir;
    write_nested_glass(dir, "glass", 10);
    const ProgramResult plain = render(dir, {"--output", "plain.gro"});
    const ProgramResult zero = render(dir, {"--output", "zero.gro", "--cutoff", "0"});
    ASSERT_EQ(plain.exit_code, 0) << plain.err;
    ASSERT_EQ(zero.exit_code, 0) << zero.err;
    EXPECT_EQ(rays_traced(plain.out), rays_traced(zero.out));
    EXPECT_EQ(read_gro(dir.path() / "plain.gro").data(), read_gro(dir.path() / "zero.gro").data());
}

TEST(RayTreeCutoff, ACutoffChangesThePictureOnlySlightly) {
    const TempDir dir;
    write_nested_glass(dir, "glass", 10);
    ASSERT_EQ(render(dir, {"--output", "plain.gro"}).exit_code, 0);
    ASSERT_EQ(render(dir, {"--output", "cut.gro", "--cutoff", "0.01"}).exit_code, 0);
    const std::vector<float> plain = read_gro(dir.path() / "plain.gro").data();
    const std::vector<float> cut = read_gro(dir.path() / "cut.gro").data();
    ASSERT_EQ(plain.size(), cut.size());
    // A branch below weight W carries at most W of the light reaching its start, and the light
    // here is at most 1 per channel, so no pixel can move by more than a few times W.
    float largest = 0.0F;
    for (std::size_t i = 0; i < plain.size(); ++i) {
        largest = std::max(largest, std::abs(plain[i] - cut[i]));
    }
    EXPECT_GT(largest, 0.0F);
    EXPECT_LT(largest, 0.05F);
}

TEST(RayTreeBoundWarning, WarnsOnceWithTheBoundAndTheWaysOut) {
    const TempDir dir;
    // Only the bottom row, which sees the matte floor, is drawn.
    write_nested_glass(dir, "glass", 30, "0 23 31 23");
    const ProgramResult r = render(dir, {});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    // Each hit sends 2 rays and each hit one shadow feeler to the one light: 2 (2^30 - 1) rays.
    const std::string warning =
        "warning: the ray tree may send up to 2.15e+09 rays per sample (maxdepth 30, and a hit "
        "can send 2 secondary rays)";
    const std::size_t at = r.err.find(warning);
    ASSERT_NE(at, std::string::npos) << r.err;
    EXPECT_EQ(r.err.find(warning, at + 1), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("lower maxdepth"), std::string::npos);
    EXPECT_NE(r.err.find("--cutoff"), std::string::npos);
}

}  // namespace
}  // namespace rt::test
