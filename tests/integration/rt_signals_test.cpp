// How rt ends on a signal: it abandons the line being drawn, writes the finished lines (beside an
// existing file, never over it), and exits with the shell's status for the signal (128 + its
// number).
#include <chrono>
#include <csignal>
#include <filesystem>
#include <string>
#include <thread>

#include "rt/image/gro_format.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "support/run_program.h"
#include "support/temp_dir.h"
#include "support/x_display.h"
#include <fcntl.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

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

// Stopped before its first line was finished, a render writes nothing, and says so once: not
// also that the finished lines are kept.
TEST(RtSignals, AnInterruptBeforeTheFirstLineSaysNothingWasKept) {
    const TempDir dir;
    // twocubes4 at a sample resolution of 64, every sample traced: seconds a line.
    std::string scene = read_text(source_dir() / "scenes" / "twocubes4.scn");
    const std::size_t at = scene.find("sample resolution x,y\n$ 4\n");
    ASSERT_NE(at, std::string::npos);
    scene.replace(at, 26, "sample resolution x,y\n$ 64\n");
    dir.write("slow.scn", scene);
    for (const char* name : {"Attributes", "cube", "checker8", "square"}) {
        std::filesystem::copy_file(source_dir() / "scenes" / name, dir.path() / name);
    }
    SpawnedProgram rt("rt",
                      {"slow", "-n", "--output", "out.gro", "--threads", "1", "-Dx", "-dc",
                       "--no-window", "--quiet"},
                      dir.path(), {std::nullopt, false});
    for (int k = 0; k < 6000 && lines_begun(rt.errors()) < 1; ++k) {
        std::this_thread::sleep_for(milliseconds(10));
    }
    ASSERT_EQ(lines_begun(rt.errors()), 1) << rt.errors().substr(0, 2000);
    rt.signal(SIGINT);
    EXPECT_EQ(rt.wait_for_exit(seconds(60)).value_or(-1), 130);
    const std::string errors = rt.errors();
    EXPECT_NE(errors.find("no file was written"), std::string::npos) << errors.substr(0, 2000);
    EXPECT_NE(errors.find("rt: interrupted\n"), std::string::npos);
    EXPECT_EQ(errors.find("the finished lines are kept"), std::string::npos);
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "out.gro"));
}

// A display that takes the connection and never answers (a stuck X server, a dead tunnel) blocks
// the window's opening. Nothing is rendered yet: the first signal ends rt there, at once.
TEST(RtSignals, TheFirstSignalEndsARunWaitingForItsDisplay) {
    const TempDir dir;
    std::filesystem::create_directories("/tmp/.X11-unix");
    int number = 700 + static_cast<int>(::getpid() % 200);
    while (std::filesystem::exists(fmt::format("/tmp/.X11-unix/X{}", number))) {
        ++number;
    }
    const std::string socket_path = fmt::format("/tmp/.X11-unix/X{}", number);
    const int server = ::socket(AF_UNIX, SOCK_STREAM, 0);
    ASSERT_GE(server, 0);
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    socket_path.copy(address.sun_path, sizeof address.sun_path - 1);
    ASSERT_EQ(::bind(server, reinterpret_cast<const sockaddr*>(&address), sizeof address), 0);
    ASSERT_EQ(::listen(server, 4), 0);  // connections wait in the queue, never answered
    {
        SpawnedProgram rt("rt",
                          {(source_dir() / "scenes" / "twocubes").string(), "-n", "--quiet",
                           "--threads", "1", "--output", "out.gro"},
                          dir.path(), {fmt::format(":{}", number), false});
        std::this_thread::sleep_for(stretched(milliseconds(1000)));  // well into the opening
        ASSERT_FALSE(rt.wait_for_exit(milliseconds(0))) << rt.errors();
        rt.signal(SIGTERM);
        EXPECT_EQ(rt.wait_for_exit(seconds(10)).value_or(-1), 143) << rt.errors();
        EXPECT_NE(rt.errors().find("rt: interrupted"), std::string::npos) << rt.errors();
    }
    ::close(server);
    std::filesystem::remove(socket_path);
}

// Whoever reads rt's messages may stop before rt does (`rt ... 2>&1 | head -1`). The messages
// after that are lost; the render is not.
TEST(RtSignals, AClosedPipeOnStandardErrorDoesNotEndTheRender) {
    const TempDir dir;
    int pipe_ends[2];
    ASSERT_EQ(::pipe(pipe_ends), 0);
    ::close(pipe_ends[0]);  // nobody reads: the first message rt writes meets a closed pipe
    posix_spawn_file_actions_t files;
    posix_spawn_file_actions_init(&files);
    posix_spawn_file_actions_adddup2(&files, pipe_ends[1], STDERR_FILENO);
    posix_spawn_file_actions_addopen(&files, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&files, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    sigset_t defaults;
    sigemptyset(&defaults);
    sigaddset(&defaults, SIGPIPE);  // as a shell starts it, whatever this test process does
    posix_spawnattr_setsigdefault(&attributes, &defaults);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF);
    const std::string program = (bin_dir() / "rt").string();
    // twocubes4 warns about its texture lines while it is read, before the render.
    std::vector<std::string> args = {program,
                                     (source_dir() / "scenes" / "twocubes4").string(),
                                     "-n",
                                     "--no-window",
                                     "-p",
                                     "--output",
                                     (dir.path() / "out.png").string()};
    std::vector<char*> argv;
    for (std::string& a : args) {
        argv.push_back(a.data());
    }
    argv.push_back(nullptr);
    pid_t pid = 0;
    ASSERT_EQ(::posix_spawn(&pid, program.c_str(), &files, &attributes, argv.data(), environ), 0);
    ::close(pipe_ends[1]);
    posix_spawn_file_actions_destroy(&files);
    posix_spawnattr_destroy(&attributes);
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    ASSERT_TRUE(WIFEXITED(status)) << "ended by signal " << WTERMSIG(status);
    EXPECT_EQ(WEXITSTATUS(status), 0);
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "out.png"));
}

}  // namespace
}  // namespace rt::test
