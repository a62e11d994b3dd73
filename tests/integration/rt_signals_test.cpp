// How rt ends on a signal: it abandons the line being drawn, writes the finished lines (beside an
// existing file, never over it), and exits with the shell's status for the signal (128 + its
// number).
#include <chrono>
#include <csignal>
#include <filesystem>
#include <string>
#include <thread>

#include "rt/image/gro_format.h"

#include <gtest/gtest.h>

#include "support/run_program.h"
#include "support/temp_dir.h"
#include "support/x_display.h"
#include <sys/stat.h>

namespace rt::test {
namespace {

using std::chrono::milliseconds;
using std::chrono::seconds;

// Counts the lines that have begun: -dc names every pixel, and each line begins at column 0.
int lines_begun(const std::string& errors) {
    int count = 0;
    for (std::size_t at = errors.find(" column 0\n"); at != std::string::npos;
         at = errors.find(" column 0\n", at + 1)) {
        ++count;
    }
    return count;
}

// Renders twocubes4 into out.gro with every sample of every pixel on one thread (about 3 s) and
// sends `signal` once the second line has begun, so the first is finished; returns the status.
int interrupt_after_first_line(const TempDir& dir, int signal, std::string& errors) {
    const std::string scene = (source_dir() / "scenes" / "twocubes4").string();
    SpawnedProgram rt("rt",
                      {scene, "-n", "--output", "out.gro", "--threads", "1", "-Dx", "-dc",
                       "--no-window", "--quiet"},
                      dir.path(), {std::nullopt, false});
    for (int k = 0; k < 6000 && lines_begun(rt.errors()) < 2; ++k) {
        std::this_thread::sleep_for(milliseconds(10));
    }
    EXPECT_GE(lines_begun(rt.errors()), 2) << "the render did not reach its second line";
    rt.signal(signal);
    const int status = rt.wait_for_exit(seconds(60)).value_or(-1);
    errors = rt.errors();
    return status;
}

// SIGTERM (what `kill` and service managers send) once exited 130, as if it were Ctrl-C.
TEST(RtSignals, SigtermStopsTheRenderKeepsItAndExits143) {
    const TempDir dir;
    std::string errors;
    ASSERT_EQ(interrupt_after_first_line(dir, SIGTERM, errors), 143) << errors;
    EXPECT_NE(errors.find("interrupted; the finished lines are kept"), std::string::npos);
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "out.gro"));
}

// An earlier picture of the same name is worth more than a partial one: the finished lines go
// beside it, into out.partial.gro, which --resume can finish.
TEST(RtSignals, AnInterruptedRenderKeepsAnExistingFile) {
    const TempDir dir;
    dir.write("out.gro", "an earlier picture");
    std::string errors;
    ASSERT_EQ(interrupt_after_first_line(dir, SIGINT, errors), 130) << errors;
    EXPECT_EQ(read_text(dir.path() / "out.gro"), "an earlier picture");
    EXPECT_NE(errors.find("out.gro is kept; the finished lines went to out.partial.gro"),
              std::string::npos)
        << errors;
    const Film part = read_gro(dir.path() / "out.partial.gro");
    EXPECT_FALSE(part.complete());
    EXPECT_LE(part.first_finished_row(), part.window().bottom);
}

// Before the render there is nothing to keep, and a read may never come back to look at the
// flag: a scene that is a named pipe nobody writes to blocks rt in open(). The first signal
// ends it there, at once.
TEST(RtSignals, TheFirstSignalEndsARunStillReadingItsScene) {
    const TempDir dir;
    ASSERT_EQ(::mkfifo((dir.path() / "stuck.scn").c_str(), 0600), 0);
    SpawnedProgram rt("rt", {"stuck", "-n", "--no-window", "--quiet", "--threads", "1"}, dir.path(),
                      {std::nullopt, false});
    std::this_thread::sleep_for(stretched(milliseconds(1000)));  // well into the blocked open
    ASSERT_FALSE(rt.wait_for_exit(milliseconds(0))) << rt.errors();
    rt.signal(SIGTERM);
    EXPECT_EQ(rt.wait_for_exit(seconds(10)).value_or(-1), 143);
    EXPECT_NE(rt.errors().find("rt: interrupted"), std::string::npos) << rt.errors();
}

}  // namespace
}  // namespace rt::test
