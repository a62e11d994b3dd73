// The rt program as a user meets it: arguments, messages, exit codes, the files it writes.
#include <algorithm>
#include <filesystem>
#include <string>

#include "rt/app/switch_table.h"

#include <gtest/gtest.h>

#include "support/run_program.h"
#include "support/temp_dir.h"
#include <unistd.h>

namespace rt::test {
namespace {

namespace fs = std::filesystem;

// A copy of the shipped scenes in a temporary folder, so tests can write beside them.
class RtProgram : public ::testing::Test {
protected:
    void SetUp() override {
        fs::copy(source_dir() / "scenes", dir_.path() / "scenes", fs::copy_options::recursive);
    }
    ProgramResult rt(const std::vector<std::string>& args) {
        return run_program("rt", args, dir_.path());
    }
    fs::path at(const std::string& name) const { return dir_.path() / name; }
    // A small window of twocubes, so that the tests stay quick.
    void write_small_scene(const std::string& name, const std::string& window) {
        std::string scene = read_text(at("scenes/twocubes.scn"));
        const std::string whole = "$ 0 0 511 399";
        scene.replace(scene.find(whole), whole.size(), "$ " + window);
        dir_.write("scenes/" + name, scene);
    }

    TempDir dir_;
};

TEST_F(RtProgram, NoArgumentsPrintsTheSwitches) {
    const ProgramResult r = rt({});
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_NE(r.out.find("-Dd"), std::string::npos);
    EXPECT_NE(r.out.find("-Stg"), std::string::npos);
}

TEST_F(RtProgram, HelpAndVersion) {
    const ProgramResult help = rt({"--help"});
    EXPECT_EQ(help.exit_code, 0);
    EXPECT_NE(help.out.find("--output"), std::string::npos);
    const ProgramResult version = rt({"--version"});
    EXPECT_EQ(version.exit_code, 0);
    EXPECT_NE(version.out.find("rt "), std::string::npos);
}

TEST_F(RtProgram, UnknownSwitchIsAUsageError) {
    const ProgramResult r = rt({"scenes/twocubes", "-Q"});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("-Q"), std::string::npos);
}

TEST_F(RtProgram, SwitchNotDoneYetFailsClearly) {
    const auto not_yet =
        std::find_if(switch_table().begin(), switch_table().end(),
                     [](const SwitchSpec& s) { return s.status == Status::NotYet; });
    if (not_yet == switch_table().end()) {
        GTEST_SKIP() << "every switch is implemented";
    }
    const ProgramResult r = rt({"scenes/twocubes", std::string(not_yet->example)});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("not implemented yet"), std::string::npos);
    EXPECT_FALSE(fs::exists(at("twocubes.gro")));
}

TEST_F(RtProgram, MissingSceneNamesTheFile) {
    const ProgramResult r = rt({"scenes/nothere"});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("nothere"), std::string::npos);
}

// Names the system cannot look up are reported as files that cannot be opened, with the reason,
// not as internal errors: a loop of links, and a name longer than the system allows.
TEST_F(RtProgram, UnlookupableSceneNamesAreInputErrors) {
    fs::create_symlink("loop.scn", at("loop.scn"));
    const ProgramResult loop = rt({"loop", "-n"});
    EXPECT_EQ(loop.exit_code, 1);
    EXPECT_NE(loop.err.find("loop.scn: cannot open the scene file"), std::string::npos) << loop.err;
    const std::string long_name(5000, 'a');
    const ProgramResult too_long = rt({long_name, "-n"});
    EXPECT_EQ(too_long.exit_code, 1);
    EXPECT_EQ(too_long.err.find("internal error"), std::string::npos) << too_long.err;
    const ProgramResult show = run_program("show", {long_name, "--output", "x.png"}, dir_.path());
    EXPECT_EQ(show.err.find("internal error"), std::string::npos) << show.err;
    EXPECT_NE(show.exit_code, 0);
}

// A scene named as given when NAME.scn does not exist: any file but a folder (a pipe from the
// shell's <(...) is read; a device is refused with that reason, not as a missing NAME.scn).
TEST_F(RtProgram, ASceneThatExistsIsTakenAsGiven) {
    const ProgramResult device = rt({"/dev/null", "-n"});
    EXPECT_EQ(device.exit_code, 1);
    EXPECT_NE(device.err.find("/dev/null: cannot open the scene file: a device, not a file"),
              std::string::npos)
        << device.err;
}

TEST_F(RtProgram, DashVDrawsTheManualsTextureMappedSurface) {
    write_small_scene("small.scn", "180 320 189 329");  // on the lenses
    const ProgramResult with = rt({"scenes/small", "-V", "-n", "--output", "v.ppm"});
    EXPECT_EQ(with.exit_code, 0) << with.err;
    EXPECT_EQ(with.err, "");
    const ProgramResult without = rt({"scenes/small", "-n", "--output", "plain.ppm"});
    EXPECT_EQ(without.exit_code, 0) << without.err;
    EXPECT_NE(without.err.find("read only with -V"), std::string::npos);
    EXPECT_NE(read_text(at("v.ppm")), read_text(at("plain.ppm")));
}

TEST_F(RtProgram, DashVWithoutTheLinesOrWithABadMapStopsAtTheLine) {
    std::string scene = read_text(at("scenes/twocubes.scn"));
    scene.erase(scene.find("$ 1\n$ 0 lenspts.dat"));
    dir_.write("scenes/nolens.scn", scene);
    const ProgramResult missing = rt({"scenes/nolens", "-V"});
    EXPECT_EQ(missing.exit_code, 1);
    EXPECT_EQ(missing.err,
              "scenes/nolens.scn:27: expected the texture-mapped surface count (-V), found "
              "end of file\n");
    std::string map = read_text(at("scenes/prescrip.dat"));
    map.replace(map.find("centre 25.5 4"), 13, "centre 25.5");
    dir_.write("scenes/prescrip.dat", map);
    const ProgramResult bad = rt({"scenes/twocubes", "-V"});
    EXPECT_EQ(bad.exit_code, 1);
    EXPECT_NE(
        bad.err.find("prescrip.dat:12: expected the v of optical centre 1, found end of line"),
        std::string::npos)
        << bad.err;
    EXPECT_FALSE(fs::exists(at("twocubes.gro")));
}

TEST_F(RtProgram, WritesGroInTheCurrentFolderWithOrWithoutScn) {
    write_small_scene("small.scn", "200 300 209 309");
    EXPECT_EQ(rt({"scenes/small"}).exit_code, 0);
    EXPECT_TRUE(fs::exists(at("small.gro")));
    fs::remove(at("small.gro"));
    EXPECT_EQ(rt({"scenes/small.scn"}).exit_code, 0);
    EXPECT_TRUE(fs::exists(at("small.gro")));
}

TEST_F(RtProgram, NoGroWithDashNButOtherOutputsStill) {
    write_small_scene("small.scn", "200 300 209 309");
    const ProgramResult r = rt({"scenes/small", "-n", "--output", "a.png", "--output", "b.ppm"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_FALSE(fs::exists(at("small.gro")));
    EXPECT_TRUE(fs::exists(at("a.png")));
    EXPECT_TRUE(fs::exists(at("b.ppm")));
}

TEST_F(RtProgram, UnknownOutputFormatIsRefusedBeforeRendering) {
    write_small_scene("small.scn", "200 300 209 309");
    const ProgramResult r = rt({"scenes/small", "--output", "a.jpg"});
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.err.find(".jpg"), std::string::npos);
}

// A missing folder is found before the render, not after it.
TEST_F(RtProgram, OutputIntoAMissingFolderIsRefusedBeforeRendering) {
    write_small_scene("small.scn", "200 300 209 309");
    const ProgramResult r = rt({"scenes/small", "--output", "good.png", "--output", "nodir/a.png"});
    EXPECT_EQ(r.exit_code, 3);
    EXPECT_NE(r.err.find("cannot write nodir/a.png: the folder nodir does not exist"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(at("small.gro")));
    EXPECT_FALSE(fs::exists(at("good.png")));
}

// The .gro goes into the current folder, which is checked the same way.
TEST_F(RtProgram, GroIntoAReadOnlyFolderIsRefusedBeforeRendering) {
    write_small_scene("small.scn", "200 300 209 309");
    fs::create_directory(at("ro"));
    fs::permissions(at("ro"), fs::perms::owner_read | fs::perms::owner_exec);
    if (::access(at("ro").c_str(), W_OK) == 0) {
        GTEST_SKIP() << "running as root: a read-only folder is writable";
    }
    const ProgramResult r =
        run_program("rt", {"../scenes/small", "--output", "../good.png"}, at("ro"));
    fs::permissions(at("ro"), fs::perms::owner_all);
    EXPECT_EQ(r.exit_code, 3);
    EXPECT_NE(
        r.err.find("cannot write small.gro: the folder . is not writable (Permission denied)"),
        std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(at("good.png")));
}

// One output that fails at the end (a folder in the way of a.png) does not cost the others:
// every output is written, each failure reported, and the exit status says one failed.
TEST_F(RtProgram, EveryOutputIsWrittenWhenOneFails) {
    write_small_scene("small.scn", "200 300 209 309");
    fs::create_directory(at("a.png"));
    fs::create_directory(at("c.ppm"));
    const ProgramResult r =
        rt({"scenes/small", "--output", "a.png", "--output", "good.png", "--output", "c.ppm"});
    EXPECT_EQ(r.exit_code, 3);
    EXPECT_NE(r.err.find("rt: cannot write a.png"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("rt: cannot write c.ppm"), std::string::npos) << r.err;
    EXPECT_TRUE(fs::exists(at("small.gro")));
    EXPECT_TRUE(fs::exists(at("good.png")));
}

TEST_F(RtProgram, BadSceneLeavesAnExistingOutputAlone) {
    dir_.write("broken.gro", "precious");
    dir_.write("broken.scn", "$ 0 2 0 0 3 .5 2 1\n$ 1 2 x\n");
    const ProgramResult r = rt({"broken"});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("broken.scn:2:"), std::string::npos) << r.err;
    EXPECT_EQ(read_text(at("broken.gro")), "precious");
}

TEST_F(RtProgram, ParseTraceWithDf) {
    write_small_scene("small.scn", "200 300 201 301");
    const ProgramResult r = rt({"scenes/small", "-n", "-df"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("small.scn:"), std::string::npos);
    EXPECT_NE(r.err.find("cube:"), std::string::npos);
}

TEST_F(RtProgram, DashLDrawsOnlyFromThatLineUp) {
    write_small_scene("small.scn", "200 300 209 309");
    const ProgramResult r = rt({"scenes/small", "-n", "-L305", "--output", "a.ppm"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    // Rows 300..305 of the window 300..309: a 10 x 6 picture.
    EXPECT_EQ(read_text(at("a.ppm")).substr(0, 8), "P6\n10 6\n");
    EXPECT_EQ(rt({"scenes/small", "-n", "-L299"}).exit_code, 2);
}

TEST_F(RtProgram, AutoCenteringPrintsTheLookPoint) {
    std::string scene = read_text(at("scenes/twocubes.scn"));
    scene.replace(scene.find("$ 0 2 1 4"), 9, "$ 1 2 1 4");
    scene.replace(scene.find("$ 0 0 511 399"), 13, "$ 0 0 3 3");
    dir_.write("scenes/centred.scn", scene);
    const ProgramResult r = rt({"scenes/centred", "-n"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("auto-centering: look point set to"), std::string::npos) << r.err;
}

TEST_F(RtProgram, ShowReadsWhatRtWrote) {
    write_small_scene("small.scn", "200 300 209 309");
    ASSERT_EQ(rt({"scenes/small", "-m2.0"}).exit_code, 0);
    const ProgramResult info = run_program("show", {"small", "--info"}, dir_.path());
    EXPECT_EQ(info.exit_code, 0) << info.err;
    EXPECT_NE(info.out.find("-m2.0"), std::string::npos) << info.out;
    const ProgramResult png = run_program("show", {"small.gro", "--output", "s.png"}, dir_.path());
    EXPECT_EQ(png.exit_code, 0) << png.err;
    EXPECT_TRUE(fs::exists(at("s.png")));
}

}  // namespace
}  // namespace rt::test

namespace rt::test {
namespace {

TEST(RtProfile, DashPPrintsCountersPerKindOfRay) {
    const TempDir dir;
    const ProgramResult r = run_program(
        "rt", {(source_dir() / "scenes/twocubes").string(), "-n", "--quiet", "-p"}, dir.path());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("eye"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("shadow feeler"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("structure:"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("time: load"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("Mrays/s of every kind"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("guarded"), std::string::npos) << r.out;
}

TEST(RtProfile, DashRFiresRandomRaysAndWritesNoPicture) {
    const TempDir dir;
    const ProgramResult r =
        run_program("rt", {(source_dir() / "scenes/twocubes").string(), "-r", "-p"}, dir.path());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("random"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("204800"), std::string::npos) << r.out;  // 512 x 400 rays
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "twocubes.gro"));
}

}  // namespace
}  // namespace rt::test

namespace rt::test {
namespace {

TEST(RtDebugColor, DashDdPrintsTheMapAndEveryPixel) {
    const TempDir dir;
    const ProgramResult r = run_program(
        "rt", {(source_dir() / "scenes/twocubes").string(), "-n", "--quiet", "-dd", "-L2"},
        dir.path());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("color map: display value = intensity x 255 x 1"), std::string::npos);
    // Rows 0..2 of a 512-wide window, drawn bottom up: row 2 first.
    std::size_t pixels = 0;
    for (std::size_t at = r.err.find("\npixel "); at != std::string::npos;
         at = r.err.find("\npixel ", at + 1)) {
        ++pixels;
    }
    EXPECT_EQ(pixels, 3U * 512U);
    EXPECT_LT(r.err.find("pixel 0 2:"), r.err.find("pixel 0 0:"));
}

TEST(RtDebugFill, DashDofTracesTheFillPlaneLevels) {
    const TempDir dir;
    const ProgramResult r = run_program(
        "rt", {(source_dir() / "scenes/twocubes").string(), "-n", "--quiet", "-op", "-dof"},
        dir.path());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    // twocubes asks for an octree of depth 4: the root always split, and no level below 4 (its
    // leaves reach 16 polygons or fewer by level 3).
    EXPECT_NE(r.err.find("fill-plane level 0: 1 nodes, 71 polygon references, 0 leaves, 1 split"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("fill-plane level 3:"), std::string::npos);
    EXPECT_EQ(r.err.find("fill-plane level 5:"), std::string::npos);
}

}  // namespace
}  // namespace rt::test
