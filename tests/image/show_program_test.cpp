// The show program end to end: exit codes, messages and files.
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "rt/image/display_mapping.h"
#include "rt/image/gro_format.h"
#include "rt/image/png_format.h"
#include "rt/image/ppm_format.h"

#include <gtest/gtest.h>

#include "support/temp_dir.h"
#include <sys/wait.h>

namespace rt {
namespace {

struct Outcome {
    int code = -1;
    std::string out;
    std::string err;
};

class ShowProgram : public testing::Test {
protected:
    void SetUp() override {
        // Every build makes show (tools/CMakeLists.txt) and the image tests depend on it, so a
        // missing program is a failure, not a reason to skip.
        show_ = test::bin_dir() / "show";
        ASSERT_TRUE(std::filesystem::exists(show_)) << "show is not built: " << show_;
        Film film(5, 4, PixelRect{0, 0, 4, 3});
        for (int y = 0; y <= 3; ++y) {
            for (int x = 0; x <= 4; ++x) {
                film.set_pixel(x, y, Rgb{0.2 * x, 0.1 * y, 0.5});
            }
        }
        film.set_first_finished_row(1);
        film.provenance = {"twocubes", "-Dd -m2", "rt 0.1.0", "2024-01-02T03:04:05Z", "", "", ""};
        film.mapping.multiplier = 2.0;
        write_gro(film, dir_.path() / "pic.gro");
        film_ = film;
    }

    // Runs show in the temp folder with args (already quoted where needed).
    Outcome run(const std::string& args) const {
        const std::filesystem::path out = dir_.path() / "stdout.txt";
        const std::filesystem::path err = dir_.path() / "stderr.txt";
        // Headless whatever the environment names: no window opens (the window tests have a
        // display of their own).
        const std::string command = "cd '" + dir_.path().string() +
                                    "' && env -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER '" +
                                    show_.string() + "' " + args + " </dev/null >'" + out.string() +
                                    "' 2>'" + err.string() + "'";
        const int status = std::system(command.c_str());  // NOLINT(concurrency-mt-unsafe)
        Outcome o;
        o.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        o.out = test::read_text(out);
        o.err = test::read_text(err);
        return o;
    }

    test::TempDir dir_;
    std::filesystem::path show_;
    Film film_;
};

TEST_F(ShowProgram, InfoDescribesThePicture) {
    const Outcome o = run("pic --info");
    EXPECT_EQ(o.code, 0) << o.err;
    EXPECT_NE(o.out.find("5 x 4 pixels"), std::string::npos) << o.out;
    EXPECT_NE(o.out.find("0 0 4 3"), std::string::npos) << o.out;
    EXPECT_NE(o.out.find("3 of 4 finished"), std::string::npos) << o.out;
    EXPECT_NE(o.out.find("multiplier 2, clipping on"), std::string::npos) << o.out;
    EXPECT_NE(o.out.find("twocubes"), std::string::npos) << o.out;
    EXPECT_NE(o.out.find("-Dd -m2"), std::string::npos) << o.out;
    EXPECT_NE(o.out.find("rt 0.1.0"), std::string::npos) << o.out;
    EXPECT_NE(o.out.find("2024-01-02T03:04:05Z"), std::string::npos) << o.out;
    // Unfinished, but written without the record a resume needs.
    EXPECT_NE(o.out.find("resume    not possible"), std::string::npos) << o.out;
}

// A 16384 x 16384 picture holds 3 GiB of pixels: --info reads its header and the file's size only.
// The pixel block is a hole in a sparse file, so the test costs no disk and no time.
TEST_F(ShowProgram, InfoReadsOnlyTheHeaderOfAHugePicture) {
    const std::string header =
        "GRO rt 1\nview 16384 16384\nwindow 0 0 16383 16383\nfirst_finished_row 0\n"
        "display_multiplier 1\ndisplay_clip on\nscene big\nswitches -n\nprogram rt 0.1.0\n"
        "created 2026-12-01T00:00:00Z\npixels rgb-float32-le\nend\n";
    const std::filesystem::path big = dir_.path() / "big.gro";
    {
        std::ofstream out(big, std::ios::binary);
        out << header;
    }
    std::filesystem::resize_file(big, header.size() + std::uint64_t{16384} * 16384 * 3 * 4);
    const Outcome o = run("big --info");
    EXPECT_EQ(o.code, 0) << o.err;
    EXPECT_NE(o.out.find("16384 x 16384 pixels"), std::string::npos) << o.out;
    EXPECT_NE(o.out.find("16384 of 16384 finished"), std::string::npos) << o.out;
    // A file that does not hold its pixels is still refused.
    std::filesystem::resize_file(big, header.size() + 12);
    EXPECT_EQ(run("big --info").code, 1);
}

TEST_F(ShowProgram, OutputConvertsWithTheStoredMapping) {
    const Outcome o = run("pic.gro --output a.png --output b.ppm");
    EXPECT_EQ(o.code, 0) << o.err;
    EXPECT_EQ(read_png(dir_.path() / "a.png"), to_display(film_));
    EXPECT_EQ(read_ppm(dir_.path() / "b.ppm"), to_display(film_));
}

// .gro to .exr and back changes nothing: the EXR keeps 32-bit floats, the windows, the rows
// finished, the display mapping and what made the picture; show reads the .exr like a .gro.
TEST_F(ShowProgram, ConvertsToExrAndBackWithoutChange) {
    const Outcome to_exr = run("pic --output pic.exr");
    EXPECT_EQ(to_exr.code, 0) << to_exr.err;
    const Outcome back = run("pic.exr --output back.gro --output back.png");
    EXPECT_EQ(back.code, 0) << back.err;
    EXPECT_EQ(test::read_text(dir_.path() / "back.gro"), test::read_text(dir_.path() / "pic.gro"));
    EXPECT_EQ(read_png(dir_.path() / "back.png"), to_display(film_));
    const Outcome info = run("pic.exr --info");
    EXPECT_NE(info.out.find("3 of 4 finished"), std::string::npos) << info.out;
    EXPECT_EQ(run("missing.exr --info").code, 3);
    dir_.write("bad.exr", "not a picture");
    EXPECT_EQ(run("bad.exr --info").code, 1);
}

TEST_F(ShowProgram, MultiplierAndClipOverrideTheStoredMapping) {
    const Outcome o = run("pic -m4 -c --output a.png");
    EXPECT_EQ(o.code, 0) << o.err;
    EXPECT_EQ(read_png(dir_.path() / "a.png"), to_display(film_, DisplayMapping{4.0, false}));
    const Outcome separate = run("pic -m 0.5 --output b.png");
    EXPECT_EQ(separate.code, 0) << separate.err;
    EXPECT_EQ(read_png(dir_.path() / "b.png"), to_display(film_, DisplayMapping{0.5, true}));
}

TEST_F(ShowProgram, WithoutADisplayPrintsTheInfoAndAHint) {
    const Outcome o = run("pic");
    EXPECT_EQ(o.code, 0) << o.err;
    EXPECT_EQ(o.out, run("pic --info").out);
    EXPECT_NE(o.err.find("use --output NAME.png to see the picture"), std::string::npos) << o.err;
}

TEST_F(ShowProgram, EveryFormOfAnOptionParsesAlike) {
    // -o and --output=FILE are --output; "-m 4" and "-m0.5" are -m, and the last one wins.
    const Outcome o = run("pic -o a.png --output=b.ppm -m 4 -m0.5 -c");
    EXPECT_EQ(o.code, 0) << o.err;
    EXPECT_EQ(read_png(dir_.path() / "a.png"), to_display(film_, DisplayMapping{0.5, false}));
    EXPECT_EQ(read_ppm(dir_.path() / "b.ppm"), to_display(film_, DisplayMapping{0.5, false}));
    const Outcome zero = run("pic -m0 --output c.png");
    EXPECT_EQ(zero.code, 0) << zero.err;
    EXPECT_EQ(read_png(dir_.path() / "c.png"), to_display(film_, DisplayMapping{0.0, true}));
}

// A .png or .ppm is a whole picture: every row finished (its window was once drawn all black,
// as a render not yet begun).
TEST_F(ShowProgram, APngOrPpmToShowHasEveryRowFinished) {
    ASSERT_EQ(run("pic --output whole.png --output whole.ppm").code, 0);
    for (const char* name : {"whole.png", "whole.ppm"}) {
        const Outcome o = run(name);
        EXPECT_EQ(o.code, 0) << o.err;
        EXPECT_NE(o.out.find("rows      4 of 4 finished"), std::string::npos) << name << o.out;
    }
}

// What show draws from a .png or .ppm it also describes and converts: --info and --output read
// it as the window does, and a .png converted to a .png is the same picture.
TEST_F(ShowProgram, APngOrPpmConvertsAndDescribesAsItShows) {
    ASSERT_EQ(run("pic --output whole.png --output whole.ppm").code, 0);
    for (const char* name : {"whole.png", "whole.ppm"}) {
        const Outcome info = run(std::string(name) + " --info");
        EXPECT_EQ(info.code, 0) << info.err;
        EXPECT_NE(info.out.find("rows      4 of 4 finished"), std::string::npos) << info.out;
        const Outcome converted = run(std::string(name) + " --output again.png");
        ASSERT_EQ(converted.code, 0) << converted.err;
        EXPECT_EQ(read_png(dir_.path() / "again.png"), read_png(dir_.path() / "whole.png"));
    }
}

TEST_F(ShowProgram, NoArgumentsOrHelpPrintUsage) {
    for (const char* args : {"", "--help", "-h", "pic --info --help"}) {
        const Outcome o = run(args);
        EXPECT_EQ(o.code, 0) << args;
        EXPECT_NE(o.out.find("Usage: show [OPTIONS] NAME\n"), std::string::npos) << o.out;
        for (const char* option :
             {"NAME", "-o,--output FILE", "--info", "-m F", "-c", "-h,--help"}) {
            EXPECT_NE(o.out.find(std::string("  ") + option + " "), std::string::npos)
                << option << " missing from:\n"
                << o.out;
        }
        EXPECT_FALSE(std::filesystem::exists(dir_.path() / "a.png"));
    }
}

TEST_F(ShowProgram, UsageErrorsSayWhatIsWrong) {
    const auto expect_usage_error = [this](const std::string& args, const std::string& message) {
        const Outcome o = run(args);
        EXPECT_EQ(o.code, 2) << args;
        EXPECT_EQ(o.err, "show: " + message + "\nshow: run 'show --help' for the options\n")
            << args;
        EXPECT_EQ(o.out, "") << args;
    };
    expect_usage_error("pic --bogus --info", "The following argument was not expected: --bogus");
    expect_usage_error("pic other --info", "The following argument was not expected: other");
    expect_usage_error("--info", "NAME is required");
    expect_usage_error("pic --output", "--output: 1 required FILE missing");
    expect_usage_error("pic --info -m", "-m: 1 required F missing");
    expect_usage_error("pic -mx --info", "-m: expected a number of at least 0, found 'x'");
    expect_usage_error("pic -m -1 --info", "-m: expected a number of at least 0, found '-1'");
}

TEST_F(ShowProgram, ErrorsMapToExitCodes) {
    EXPECT_EQ(run("missing --info").code, 3);
    dir_.write("bad.gro", "GRO rt 9\n");
    const Outcome bad = run("bad --info");
    EXPECT_EQ(bad.code, 1);
    EXPECT_EQ(bad.err, "show: bad.gro:1: expected .gro format version 1, found version '9'\n");
    const Outcome jpg = run("pic --output x.jpg");
    EXPECT_EQ(jpg.code, 2);
    EXPECT_EQ(jpg.err.rfind("show: cannot write 'x.jpg': unknown image format '.jpg'", 0), 0U)
        << jpg.err;
    EXPECT_FALSE(std::filesystem::exists(dir_.path() / "x.jpg"));
}

}  // namespace
}  // namespace rt
