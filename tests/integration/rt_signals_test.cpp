// How rt ends on a signal: it stops at the end of the line being drawn, writes the finished lines,
// and exits with the shell's status for the signal (128 + its number).
#include <chrono>
#include <csignal>
#include <filesystem>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "support/temp_dir.h"
#include "support/x_display.h"

namespace rt::test {
namespace {

using std::chrono::milliseconds;
using std::chrono::seconds;

// SIGTERM (what `kill` and service managers send) once exited 130, as if it were Ctrl-C.
TEST(RtSignals, SigtermStopsTheRenderKeepsItAndExits143) {
    const TempDir dir;
    const std::string scene = (source_dir() / "scenes" / "twocubes4").string();
    // Every sample of every pixel on one thread (about 3 s); -dc names each column as it is
    // drawn, so the test knows the render has begun before it sends the signal.
    SpawnedProgram rt("rt",
                      {scene, "-n", "--output", "part.gro", "--threads", "1", "-Dx", "-dc",
                       "--no-window", "--quiet"},
                      dir.path(), {std::nullopt, false});
    for (int k = 0; k < 3000 && rt.errors().find("column") == std::string::npos; ++k) {
        std::this_thread::sleep_for(milliseconds(10));
    }
    ASSERT_NE(rt.errors().find("column"), std::string::npos) << "the render did not begin";
    rt.signal(SIGTERM);
    ASSERT_EQ(rt.wait_for_exit(seconds(60)), 143) << rt.errors();
    EXPECT_NE(rt.errors().find("interrupted; the finished lines were written"), std::string::npos);
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "part.gro"));
}

}  // namespace
}  // namespace rt::test
