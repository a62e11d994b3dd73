// SDL2 (the window), Assimp (model files) and MPI (under mpirun) are loaded only when a run
// wants them (core/shared_library.h), so that they do not slow every start:
// no program names them in its dynamic section, and when they cannot be loaded, rt and show say so
// as they do for a missing display, a build without them or a model they cannot read (and rt
// under mpirun stops with one error). A file that is no library, put first on LD_LIBRARY_PATH
// under the library's soname, stands for a missing library.
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "support/run_program.h"
#include "support/temp_dir.h"

namespace rt::test {
namespace {

namespace fs = std::filesystem;

TEST(OnDemandLibraries, NoProgramNamesSdlAssimpOrMpiInItsDynamicSection) {
    const TempDir dir;
    if (run_shell("command -v readelf", dir.path()).exit_code != 0) {
        GTEST_SKIP() << "readelf is missing (binutils)";
    }
    for (const char* program : {"rt", "show", "merge"}) {
        SCOPED_TRACE(program);
        const ProgramResult r =
            run_shell("readelf -d " + shell_quote((bin_dir() / program).string()), dir.path());
        ASSERT_EQ(r.exit_code, 0) << r.out;
        ASSERT_NE(r.out.find("(NEEDED)"), std::string::npos) << r.out;  // read as expected
        for (const std::string& line : lines_of(r.out)) {
            if (line.find("(NEEDED)") != std::string::npos) {
                EXPECT_EQ(line.find("libSDL2"), std::string::npos) << line;
                EXPECT_EQ(line.find("libassimp"), std::string::npos) << line;
                EXPECT_EQ(line.find("libmpi"), std::string::npos) << line;
            }
        }
    }
}

// The programs run with a display named and `soname` replaced by a file that is no library.
class WithoutTheLibrary : public ::testing::Test {
protected:
    // `environment`: more NAME=VALUE words for env, before the program.
    ProgramResult run(const std::string& soname, const std::string& program,
                      const std::vector<std::string>& args, const std::string& environment = "") {
        const fs::path libraries = dir_.path() / "libraries";
        fs::create_directory(libraries);
        dir_.write("libraries/" + soname, "not a shared library\n");
        // A display that is never reached: the library is loaded (and fails) before SDL looks.
        std::string command = fmt::format(
            "env -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER LD_LIBRARY_PATH={} DISPLAY=:rt-none {} {}",
            shell_quote(libraries.string()), environment,
            shell_quote((bin_dir() / program).string()));
        for (const std::string& a : args) {
            command += ' ';
            command += shell_quote(a);
        }
        return run_shell(command, dir_.path());
    }
    // twocubes4 (or `scene`) into `output` only (-n: no .gro).
    std::vector<std::string> render(const std::string& output,
                                    const std::string& scene = "twocubes4") const {
        const std::string path = (source_dir() / "scenes" / scene).string();
        return {path, "-n", "--threads", "2", "--output", (dir_.path() / output).string()};
    }

    TempDir dir_;
};

TEST_F(WithoutTheLibrary, SdlRendersWithoutAWindowAndShowSummarises) {
    const ProgramResult r = run("libSDL2-2.0.so.0", "rt", render("a.ppm"));
    EXPECT_EQ(r.exit_code, 0) << r.out;
    // The build has SDL2 but cannot load it, or lacks it.
    EXPECT_TRUE(r.out.find("rt: warning: no window: cannot load libSDL2-2.0.so.0: ") !=
                    std::string::npos ||
                r.out.find("built without SDL2") != std::string::npos)
        << r.out;
    ASSERT_TRUE(fs::exists(dir_.path() / "a.ppm"));

    const ProgramResult s = run("libSDL2-2.0.so.0", "show", {(dir_.path() / "a.ppm").string()});
    EXPECT_EQ(s.exit_code, 0) << s.out;
    EXPECT_NE(s.out.find("size      512 x 400 pixels"), std::string::npos) << s.out;
    EXPECT_TRUE(s.out.find("show: no window: cannot load libSDL2-2.0.so.0: ") !=
                    std::string::npos ||
                s.out.find("built without SDL2") != std::string::npos)
        << s.out;
}

TEST_F(WithoutTheLibrary, AssimpIsOneErrorForAModelAndNoneWithout) {
    std::vector<std::string> args = render("a.ppm", "bunny");
    args.push_back("--no-window");
    const ProgramResult r = run("libassimp.so.5", "rt", args);
    EXPECT_EQ(r.exit_code, 1) << r.out;
    // As for a model it cannot read: the model's name, then the library's.
    EXPECT_NE(r.out.find("bunny.ply: cannot read the model: cannot load libassimp.so.5: "),
              std::string::npos)
        << r.out;
    EXPECT_EQ(lines_of(r.out).size(), 1U) << r.out;
    EXPECT_FALSE(fs::exists(dir_.path() / "a.ppm"));

    // A scene without models never loads it.
    std::vector<std::string> plain = render("b.ppm");
    plain.push_back("--no-window");
    const ProgramResult p = run("libassimp.so.5", "rt", plain);
    EXPECT_EQ(p.exit_code, 0) << p.out;
    EXPECT_EQ(p.out.find("libassimp"), std::string::npos) << p.out;
    EXPECT_TRUE(fs::exists(dir_.path() / "b.ppm"));
}

// A run that no MPI launcher started never loads libmpi: were it loaded, the file in its place
// would fail the run.
TEST_F(WithoutTheLibrary, MpiIsNotLoadedOutsideMpirun) {
    std::vector<std::string> args = render("a.ppm");
    args.emplace_back("--no-window");
    const ProgramResult r = run("libmpi.so.40", "rt", args);
    EXPECT_EQ(r.exit_code, 0) << r.out;
    EXPECT_EQ(r.out.find("libmpi"), std::string::npos) << r.out;
    EXPECT_TRUE(fs::exists(dir_.path() / "a.ppm"));
}

// Under a launcher (its variable set, as mpirun sets it for each process), libmpi is loaded
// before anything else happens; when it cannot be, one line names it and the run fails (exit 5,
// a cluster failure), writing nothing.
TEST_F(WithoutTheLibrary, MpiUnderALauncherIsOneErrorAndExitFive) {
#ifndef RT_WITH_MPI
    GTEST_SKIP() << "this build of rt has no MPI";
#endif
    std::vector<std::string> args = render("a.ppm");
    args.emplace_back("--no-window");
    const ProgramResult r = run("libmpi.so.40", "rt", args, "OMPI_COMM_WORLD_SIZE=1");
    EXPECT_EQ(r.exit_code, 5) << r.out;
    const std::vector<std::string> lines = lines_of(r.out);
    ASSERT_EQ(lines.size(), 1U) << r.out;
    EXPECT_EQ(lines[0].rfind("rt: cannot load libmpi.so.40: ", 0), 0U) << r.out;
    EXPECT_NE(lines[0].find("mpirun"), std::string::npos) << r.out;
    EXPECT_FALSE(fs::exists(dir_.path() / "a.ppm"));
}

}  // namespace
}  // namespace rt::test
