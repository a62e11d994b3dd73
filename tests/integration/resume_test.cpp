// An interrupted render and rt --resume: the signal stops the render inside the ray tree, the
// .gro keeps the finished rows, and --resume completes it into the very picture an uninterrupted
// render gives, whatever the thread counts. A resume is refused when the result could differ.
#include <chrono>
#include <csignal>
#include <filesystem>
#include <string>
#include <thread>

#include "rt/image/gro_format.h"

#include <gtest/gtest.h>

#include "nested_glass.h"
#include "support/run_program.h"
#include "support/temp_dir.h"
#include "support/x_display.h"

namespace rt::test {
namespace {

namespace fs = std::filesystem;
using std::chrono::milliseconds;
using std::chrono::seconds;

// Waits, with a generous deadline, until the program's standard error holds `text`.
bool wait_for_errors(const SpawnedProgram& program, const std::string& text) {
    const auto until = std::chrono::steady_clock::now() + seconds(120);
    while (program.errors().find(text) == std::string::npos) {
        if (std::chrono::steady_clock::now() > until) {
            return false;
        }
        std::this_thread::sleep_for(milliseconds(10));
    }
    return true;
}

// Starts the render of glass.scn on one thread, naming each pixel as it starts (-dc), and sends
// `signal` once the pixel (0, line) has begun: the rows below it are finished by then.
int interrupt_at_line(const TempDir& dir, int line, int signal) {
    SpawnedProgram rt(
        "rt",
        {"glass", "-n", "-dc", "--output", "part.gro", "--threads", "1", "--no-window", "--quiet"},
        dir.path(), {std::nullopt, false});
    if (!wait_for_errors(rt, "line " + std::to_string(line) + " column 0")) {
        ADD_FAILURE() << "the render did not reach line " << line << ":\n" << rt.errors();
        return -1;
    }
    rt.signal(signal);
    const std::optional<int> status = rt.wait_for_exit(seconds(120));
    EXPECT_NE(rt.errors().find("interrupted; the finished lines are kept"), std::string::npos)
        << rt.errors();
    return status.value_or(-1);
}

// Maxdepth 40 doubles the ray tree 39 times: a row through the glass would take years. The bottom
// rows see the floor and finish at once; Ctrl-C arrives in a glass row and must end it there.
TEST(InterruptedRender, CtrlCStopsInsideTheRayTreeKeepingTheFinishedRows) {
    const TempDir dir;
    write_nested_glass(dir, "glass", 40);
    ASSERT_EQ(interrupt_at_line(dir, 18, SIGINT), 130);
    const Film part = read_gro(dir.path() / "part.gro");
    EXPECT_FALSE(part.complete());
    EXPECT_LE(part.first_finished_row(), 19);  // line 18 had begun: 19 to 23 were finished
    for (int y = part.first_finished_row(); y <= part.window().bottom; ++y) {
        float row = 0.0F;
        for (int x = 0; x < part.width(); ++x) {
            const Rgb c = part.pixel(x, y);
            row += static_cast<float>(c.r + c.g + c.b);
        }
        EXPECT_GT(row, 0.0F) << "line " << y << " is finished but black";
    }
}

TEST(InterruptedRender, SigtermExits143AndResumeCompletesItBitForBit) {
    const TempDir dir;
    write_nested_glass(dir, "glass", 13);
    // The uninterrupted picture, on two threads.
    const ProgramResult whole = run_program(
        "rt",
        {"glass", "-n", "-dc", "--output", "whole.gro", "--threads", "2", "--no-window", "--quiet"},
        dir.path());
    ASSERT_EQ(whole.exit_code, 0) << whole.err;

    ASSERT_EQ(interrupt_at_line(dir, 8, SIGTERM), 143);
    const GroHeader header = read_gro_header_only(dir.path() / "part.gro");
    ASSERT_GT(header.first_finished_row, 0);
    EXPECT_NE(header.provenance.arguments.find("glass"), std::string::npos);
    EXPECT_EQ(header.provenance.seed, "0");
    EXPECT_EQ(header.provenance.inputs.rfind("fnv1a64:", 0), 0U) << header.provenance.inputs;
    const ProgramResult info = run_program("show", {"part.gro", "--info"}, dir.path());
    EXPECT_NE(info.out.find("resume    rt --resume FILE.gro renders the missing rows"),
              std::string::npos)
        << info.out;

    // Resumed on three threads, from the recorded scene and switches.
    const ProgramResult resumed = run_program(
        "rt", {"--resume", "part.gro", "--threads", "3", "--no-window", "--quiet"}, dir.path());
    ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
    const Film done = read_gro(dir.path() / "part.gro");
    EXPECT_TRUE(done.complete());
    EXPECT_EQ(done.data(), read_gro(dir.path() / "whole.gro").data());

    const ProgramResult again = run_program("rt", {"--resume", "part.gro"}, dir.path());
    EXPECT_EQ(again.exit_code, 2);
    EXPECT_NE(again.err.find("part.gro is complete: there is nothing to resume"), std::string::npos)
        << again.err;
}

class RefusedResume : public ::testing::Test {
protected:
    void SetUp() override {
        write_nested_glass(dir_, "glass", 40);
        ASSERT_EQ(interrupt_at_line(dir_, 18, SIGINT), 130);
    }
    ProgramResult resume(std::vector<std::string> arguments) const {
        arguments.insert(arguments.begin(), {"--resume", "part.gro", "--no-window", "--quiet"});
        return run_program("rt", arguments, dir_.path());
    }
    TempDir dir_;
};

TEST_F(RefusedResume, WhenTheSceneChanged) {
    dir_.write("Attributes", read_text(dir_.path() / "Attributes") + "\n");
    const ProgramResult r = resume({});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("the scene's files have changed since the render began"),
              std::string::npos)
        << r.err;
}

TEST_F(RefusedResume, WhenOtherSwitchesAreGiven) {
    const ProgramResult r = resume({"glass", "-n", "-dc", "-m2"});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("was rendered with 'glass -n -dc', but this command gives 'glass -n -dc "
                         "-m2'"),
              std::string::npos)
        << r.err;
    const ProgramResult seed = resume({"-dc", "glass", "-n", "--seed", "3"});
    EXPECT_EQ(seed.exit_code, 2);
    EXPECT_NE(seed.err.find("but this command gives"), std::string::npos) << seed.err;
}

TEST_F(RefusedResume, WhenTheFileRecordsNothing) {
    // A header without the arguments line, as files written before resume was possible.
    std::string text = read_text(dir_.path() / "part.gro");
    const std::size_t at = text.find("arguments ");
    ASSERT_NE(at, std::string::npos);
    text.erase(at, text.find('\n', at) + 1 - at);
    dir_.write("old.gro", text);
    const ProgramResult r = run_program("rt", {"--resume", "old.gro"}, dir_.path());
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("old.gro does not record what rendered it"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace rt::test
