// rt's window (docs/window.md) on an Xvfb display the test starts itself: the finished picture on
// the screen is the one rt writes; early in a render the bottom lines are done and the top still
// shows the wireframe; and rt never waits for a key unless a person at a terminal can press one.
// show opens a picture, and + changes its exposure. Screenshots are taken with xwd and converted
// with ImageMagick, keys typed with xdotool: tools independent of rt.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "rt/image/gro_format.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "nested_glass.h"
#include "support/hand_readers.h"
#include "support/run_program.h"
#include "support/temp_dir.h"
#include "support/x_display.h"

namespace rt::test {
namespace {

using std::chrono::milliseconds;
using std::chrono::seconds;

constexpr int kRounding = 1;  // display values may differ by one step of 255

std::string scene_path(const std::string& name) {
    return (source_dir() / "scenes" / name).string();
}

// Skips the calling test when the display tools are missing (scripts/install-deps has them).
#define SKIP_WITHOUT_DISPLAY_TOOLS()                                     \
    if (const std::string why = missing_display_tools(); !why.empty()) { \
        GTEST_SKIP() << why;                                             \
    }

// twocubes4 at a sample resolution of 8 (64 samples a pixel instead of 16), written into `folder`
// with the files it names: on one thread its rows take long enough to be caught half done by a
// screenshot however busy the machine is (twocubes4 itself could end before the first one).
std::string slow_twocubes(const TempDir& folder) {
    for (const char* name :
         {"Attributes", "cube", "checker8", "square", "lenspts.dat", "prescrip.dat"}) {
        std::filesystem::copy_file(source_dir() / "scenes" / name, folder.path() / name);
    }
    std::string text = read_text(source_dir() / "scenes" / "twocubes4.scn");
    const std::string four = "sample resolution x,y\n$ 4\n";
    const std::size_t at = text.find(four);
    EXPECT_NE(at, std::string::npos) << "twocubes4.scn has changed";
    if (at != std::string::npos) {
        text.replace(at, four.size(), "sample resolution x,y\n$ 8\n");
    }
    return folder.write("slow.scn", text).string();
}

Image8 read_ppm(const std::filesystem::path& path) {
    return parse_ppm(read_text(path));
}

bool rows_match(const Image8& a, const Image8& b, int y) {
    const auto start = static_cast<std::size_t>(y) * static_cast<std::size_t>(a.width) * 3;
    for (std::size_t i = start; i < start + static_cast<std::size_t>(a.width) * 3; ++i) {
        if (std::abs(int(a.rgb[i]) - int(b.rgb[i])) > kRounding) {
            return false;
        }
    }
    return true;
}

bool pictures_match(const Image8& a, const Image8& b) {
    if (a.width != b.width || a.height != b.height) {
        return false;
    }
    for (int y = 0; y < a.height; ++y) {
        if (!rows_match(a, b, y)) {
            return false;
        }
    }
    return true;
}

bool row_is_black(const Image8& a, int y) {
    const auto start = a.rgb.begin() + static_cast<std::ptrdiff_t>(y) * a.width * 3;
    return std::all_of(start, start + static_cast<std::ptrdiff_t>(a.width) * 3,
                       [](std::uint8_t v) { return v == 0; });
}

// Screenshots until `good` holds for one (returned), or none within the limit (empty picture).
template <typename Shoot, typename Good>
Image8 shoot_until(Shoot shoot, seconds limit, Good good) {
    const auto until = std::chrono::steady_clock::now() + stretched(limit);
    while (std::chrono::steady_clock::now() < until) {
        Image8 shot = shoot();
        if (shot.width > 0 && good(shot)) {
            return shot;
        }
        // Each shot starts X clients; a pause keeps them from crowding the server's queue.
        std::this_thread::sleep_for(milliseconds(20));
    }
    return {};
}

// Screenshots of the window with this title until `good` holds for one (returned), or none
// within the limit (an empty picture).
template <typename Good>
Image8 screenshot_until(const XDisplay& x, const std::string& title, seconds limit, Good good) {
    return shoot_until([&] { return screenshot(x.name(), title); }, limit, good);
}

// A program started in `program` and shot until `good` holds for a shot (returned; empty when
// none does within the limit). One that found no window (`found_no_window`, asked after a
// fruitless search) is started once more, for that case alone: a loaded X server was seen to
// refuse a client for a moment. The first start's words go to `earlier_errors`, for the report.
struct ProgramStart {
    std::string name;
    std::vector<std::string> args;
    std::filesystem::path folder;
    SpawnSettings settings;
};
template <typename Shoot, typename Good, typename FoundNoWindow>
Image8 start_and_shoot(std::optional<SpawnedProgram>& program, const ProgramStart& start,
                       Shoot shoot, seconds limit, Good good, FoundNoWindow found_no_window,
                       std::string& earlier_errors) {
    Image8 shot;
    for (int attempt = 0; attempt < 2 && shot.width == 0; ++attempt) {
        if (program) {
            earlier_errors += program->errors();
        }
        program.emplace(start.name, start.args, start.folder, start.settings);
        shot = shoot_until(shoot, limit, good);
        if (shot.width == 0 && !found_no_window(*program)) {
            break;  // it has a window that shows something else: no second start
        }
    }
    return shot;
}

TEST(Window, ShowsTheFinishedPictureAndWaitsForEnter) {
    SKIP_WITHOUT_DISPLAY_TOOLS();
    const XDisplay x;
    ASSERT_TRUE(x.running());
    const TempDir dir;
    const std::string scene = scene_path("twocubes");
    SpawnedProgram rt("rt", {scene, "-n", "--output", "final.ppm", "--quiet"}, dir.path(),
                      {x.name(), true});
    ASSERT_TRUE(wait_for_file(dir.path() / "final.ppm", seconds(60))) << rt.errors();
    const Image8 written = read_ppm(dir.path() / "final.ppm");
    // The display thread redraws within a frame of the last row; allow it a moment.
    const Image8 shown = screenshot_until(
        x, "rt: " + scene, seconds(5), [&](const Image8& s) { return pictures_match(s, written); });
    EXPECT_EQ(shown.width, 512);
    EXPECT_EQ(shown.height, 400) << "the window never showed the picture rt wrote";
    // The picture is written and rt waits for Enter on its terminal, then ends.
    EXPECT_FALSE(rt.wait_for_exit(milliseconds(300))) << "rt did not wait for Enter";
    rt.type_line("");
    EXPECT_EQ(rt.wait_for_exit(seconds(10)), 0) << rt.errors();
}

TEST(Window, EarlyInARenderShowsBottomLinesDoneAndTheWireframeAbove) {
    SKIP_WITHOUT_DISPLAY_TOOLS();
    const XDisplay x;
    ASSERT_TRUE(x.running());
    const TempDir dir;
    const std::string scene = slow_twocubes(dir);
    ASSERT_EQ(run_program("rt", {scene, "-w", "-n", "--output", "wire.ppm"}, dir.path()).exit_code,
              0);
    const Image8 wire = read_ppm(dir.path() / "wire.ppm");
    const int last = wire.height - 1;
    // What the shots saw, for the report when none will do.
    int shots = 0;
    int windows = 0;
    bool last_top_is_wireframe = false;
    int last_rows_changed = 0;
    // The first screenshot where the picture has replaced some of the wireframe: its top row is
    // still the wireframe's, and some row is neither the wireframe's nor black (a window not yet
    // drawn, or drawn in part, shows black where the wireframe has lines).
    const auto replaced_some = [&](const Image8& s) {
        ++windows;
        last_top_is_wireframe = s.height == wire.height && rows_match(s, wire, 0);
        last_rows_changed = 0;
        for (int y = last; y > 0 && s.height == wire.height; --y) {
            last_rows_changed += !rows_match(s, wire, y) && !row_is_black(s, y) ? 1 : 0;
        }
        return last_top_is_wireframe && last_rows_changed > 0;
    };
    // rt asks the display three times for its window; should it still have none, it warns
    // "no window: ..." and renders headless. One thread, so that rows finish strictly from the
    // bottom up and slowly enough to be seen.
    std::optional<SpawnedProgram> rt;
    std::string earlier_errors;
    const Image8 early = start_and_shoot(
        rt,
        {"rt",
         {scene, "-n", "--output", "part.ppm", "--output", "part.gro", "--threads", "1", "--quiet"},
         dir.path(),
         {x.name(), false}},
        [&] {
            ++shots;
            return screenshot(x.name(), "rt: " + scene);
        },
        seconds(30), replaced_some,
        [](const SpawnedProgram& p) { return p.errors().find("no window") != std::string::npos; },
        earlier_errors);
    // Ctrl-C stops the render; the finished lines are written, the rest black.
    rt->signal(SIGINT);
    ASSERT_EQ(rt->wait_for_exit(seconds(30)), 130) << rt->errors();
    ASSERT_EQ(early.height, wire.height)
        << "no screenshot showed a finished line: " << shots << " shots, " << windows
        << " found the window; in the last, the top row is "
        << (last_top_is_wireframe ? "" : "not ") << "the wireframe's and " << last_rows_changed
        << " rows are neither the wireframe's nor black. rt said: " << earlier_errors
        << rt->errors();
    const Image8 part = read_ppm(dir.path() / "part.ppm");
    const int finished =
        std::stoi(parse_gro(dir.path() / "part.gro").header.at("first_finished_row"));
    // The first row from the bottom that the screenshot does not show finished.
    int split = last;
    while (split >= finished && rows_match(early, part, split)) {
        --split;
    }
    bool picture_differs_from_wireframe = false;
    for (int y = split + 1; y <= last; ++y) {
        picture_differs_from_wireframe =
            picture_differs_from_wireframe || !rows_match(wire, part, y);
    }
    EXPECT_TRUE(picture_differs_from_wireframe) << "the bottom lines show no picture";
    EXPECT_GT(split, 0) << "the render was over before the screenshot";
    int wire_rows_with_lines = 0;
    for (int y = 0; y <= split; ++y) {
        EXPECT_TRUE(rows_match(early, wire, y) || y == split)
            << "row " << y << " is neither finished nor wireframe";
        wire_rows_with_lines += row_is_black(wire, y) ? 0 : 1;
    }
    EXPECT_GT(wire_rows_with_lines, 10) << "the top should show the wireframe's lines";
}

TEST(Window, NeverWaitsWithoutADisplayOrATerminal) {
    SKIP_WITHOUT_DISPLAY_TOOLS();
    const XDisplay x;
    ASSERT_TRUE(x.running());
    const TempDir dir;
    const std::string scene = scene_path("twocubes");
    const std::vector<std::string> args = {scene, "-n", "--output", "a.ppm", "--quiet"};
    {
        SCOPED_TRACE("DISPLAY unset, on a terminal");
        SpawnedProgram rt("rt", args, dir.path(), {std::nullopt, true});
        EXPECT_EQ(rt.wait_for_exit(seconds(30)), 0) << rt.errors();
    }
    {
        SCOPED_TRACE("--no-window on a display, on a terminal");
        std::vector<std::string> no_window = args;
        no_window.emplace_back("--no-window");
        SpawnedProgram rt("rt", no_window, dir.path(), {x.name(), true});
        EXPECT_EQ(rt.wait_for_exit(seconds(30)), 0) << rt.errors();
    }
    {
        SCOPED_TRACE("a display, standard input not a terminal: the window opens and closes");
        // Slow enough (about 10 s of work) that the window is seen before rt ends on a busy
        // machine.
        const std::string slow = slow_twocubes(dir);
        SpawnedProgram rt("rt", {slow, "-n", "-L250", "--output", "b.ppm", "--quiet"}, dir.path(),
                          {x.name(), false});
        const Image8 shown =
            screenshot_until(x, "rt: " + slow, seconds(20), [](const Image8&) { return true; });
        EXPECT_EQ(shown.width, 512) << "no window opened";
        // About 10 s of work, which a machine loaded by other jobs can stretch past 30 s: the
        // limit only has to tell a render that ends from one that waits for a key.
        EXPECT_EQ(rt.wait_for_exit(seconds(120)), 0) << rt.errors();
    }
    {
        SCOPED_TRACE("a display that cannot be reached");
        SpawnedProgram rt("rt", args, dir.path(), {":99999", true});
        EXPECT_EQ(rt.wait_for_exit(seconds(30)), 0) << rt.errors();
        // Its warning names the display tried, so that a mistyped DISPLAY shows.
        SpawnedProgram told("rt", {scene, "-n", "--output", "c.ppm"}, dir.path(),
                            {":99999", false});
        EXPECT_EQ(told.wait_for_exit(seconds(30)), 0) << told.errors();
        EXPECT_NE(told.errors().find("no window on X display ':99999': "), std::string::npos)
            << told.errors();
    }
}

// xdotool's answer (its standard output) on the display, or "" when it fails.
std::string xdotool(const XDisplay& x, const std::string& args) {
    const std::string command = "DISPLAY='" + x.name() + "' xdotool " + args + " 2>/dev/null";
    FILE* pipe = ::popen(command.c_str(), "r");
    std::string text;
    std::array<char, 512> chunk{};
    while (pipe != nullptr && std::fgets(chunk.data(), chunk.size(), pipe) != nullptr) {
        text += chunk.data();
    }
    if (pipe != nullptr) {
        ::pclose(pipe);
    }
    return text;
}

TEST(Window, ShowDisplaysThePictureAndChangesItsExposureWithKeys) {
    SKIP_WITHOUT_DISPLAY_TOOLS();
    if (std::system("command -v xdotool >/dev/null") != 0) {  // NOLINT(concurrency-mt-unsafe)
        GTEST_SKIP() << "xdotool is not installed (scripts/install-deps installs it)";
    }
    const XDisplay x;
    ASSERT_TRUE(x.running());
    const TempDir dir;
    ASSERT_EQ(run_program("rt", {scene_path("twocubes"), "-n", "--output", "pic.gro"}, dir.path())
                  .exit_code,
              0);
    const std::string brighter = "-m" + fmt::format("{}", std::sqrt(2.0));  // one press of +
    for (const auto& [args, file] :
         {std::pair{std::vector<std::string>{}, "plain.ppm"}, {{brighter}, "bright.ppm"}}) {
        std::vector<std::string> convert = {"pic.gro", "--output", file};
        convert.insert(convert.end(), args.begin(), args.end());
        ASSERT_EQ(run_program("show", convert, dir.path()).exit_code, 0);
    }
    // Its title changes with the pointer: it is found by the start of its title.
    const auto shoot = [&] {
        const unsigned long id =
            std::strtoul(xdotool(x, "search --name '^show: pic.gro'").c_str(), nullptr, 10);
        return id == 0 ? Image8{} : screenshot_of(x.name(), id);
    };
    const Image8 plain = read_ppm(dir.path() / "plain.ppm");
    // show exits at once (status 0, "no window: ..." on its standard error) when it cannot reach
    // the display.
    std::optional<SpawnedProgram> show;
    std::string earlier_errors;
    const Image8 drawn = start_and_shoot(
        show, {"show", {"pic.gro"}, dir.path(), {x.name(), false}}, shoot, seconds(10),
        [&](const Image8& s) { return pictures_match(s, plain); },
        [](SpawnedProgram& p) { return p.wait_for_exit(milliseconds(0)).has_value(); },
        earlier_errors);
    EXPECT_EQ(drawn.width, 512) << "show never drew the picture; its errors: " << earlier_errors
                                << show->errors();
    // The pointer over the picture and + pressed (keys go to the window under the pointer).
    xdotool(x, "mousemove 100 300 key plus");
    const Image8 bright = read_ppm(dir.path() / "bright.ppm");
    EXPECT_EQ(
        shoot_until(shoot, seconds(10), [&](const Image8& s) { return pictures_match(s, bright); })
            .width,
        512)
        << "+ did not show the picture at " << brighter << "; show's errors: " << show->errors();
    const std::string name = xdotool(x, "search --name '^show: ' getwindowname");
    EXPECT_NE(name.find("-m1.41"), std::string::npos) << name;
    EXPECT_NE(name.find("(100, 300) = "), std::string::npos) << name;
    xdotool(x, "key Escape");
    EXPECT_EQ(show->wait_for_exit(seconds(10)), 0) << show->errors();
}

// Closing the window stops the render as Ctrl-C does: at once, even deep in a ray tree (the nested
// glass cubes at maxdepth 40 would take years), keeping the finished floor rows.
TEST(Window, EscapeStopsARenderDeepInTheRayTree) {
    SKIP_WITHOUT_DISPLAY_TOOLS();
    if (std::system("command -v xdotool >/dev/null") != 0) {  // NOLINT(concurrency-mt-unsafe)
        GTEST_SKIP() << "xdotool is not installed (scripts/install-deps installs it)";
    }
    const XDisplay x;
    ASSERT_TRUE(x.running());
    const TempDir dir;
    write_nested_glass(dir, "glass", 40);
    SpawnedProgram rt("rt", {"glass", "-n", "-dc", "--output", "part.gro", "--threads", "1"},
                      dir.path(), {x.name(), false});
    const auto until = std::chrono::steady_clock::now() + seconds(120);
    while (rt.errors().find("line 18 column 0") == std::string::npos &&
           std::chrono::steady_clock::now() < until) {
        std::this_thread::sleep_for(milliseconds(10));
    }
    ASSERT_NE(rt.errors().find("line 18 column 0"), std::string::npos) << rt.errors();
    // Esc goes to the window under the pointer (the 32 x 24 window at the top left corner); a key
    // sent before the pointer has arrived may be lost, so it is sent until the program ends.
    std::optional<int> status;
    while (!status && std::chrono::steady_clock::now() < until) {
        xdotool(x, "mousemove 5 5 sleep 0.2 key Escape");
        status = rt.wait_for_exit(milliseconds(500));
    }
    ASSERT_EQ(status, 130) << rt.errors();
    const Film part = read_gro(dir.path() / "part.gro");
    EXPECT_FALSE(part.complete());
    EXPECT_LE(part.first_finished_row(), 19);
}

// The X server going away under the window (it crashed, or the session closed) loses the window,
// not the render: rt says so and renders on to the end, and writes the whole picture. Xlib's own
// handler would end rt at once (status 1), losing everything.
TEST(Window, TheRenderGoesOnWhenTheDisplayGoesAway) {
    SKIP_WITHOUT_DISPLAY_TOOLS();
    XDisplay x;
    ASSERT_TRUE(x.running());
    const TempDir dir;
    const std::string scene = slow_twocubes(dir);
    std::optional<SpawnedProgram> rt;
    std::string earlier_errors;
    const Image8 shown = start_and_shoot(
        rt,
        {"rt",
         {scene, "-n", "--output", "whole.gro", "--threads", "1"},
         dir.path(),
         {x.name(), false}},
        [&] { return screenshot(x.name(), "rt: " + scene); }, seconds(20),
        [](const Image8& s) { return s.width == 512; },
        [](SpawnedProgram& p) { return p.errors().find("no window") != std::string::npos; },
        earlier_errors);
    ASSERT_EQ(shown.width, 512) << "rt opened no window: " << earlier_errors << rt->errors();
    x.stop();
    ASSERT_EQ(rt->wait_for_exit(seconds(120)), 0) << rt->errors();
    EXPECT_NE(rt->errors().find("lost the window: X display '" + x.name() +
                                "' closed the connection; rt goes on without it"),
              std::string::npos)
        << rt->errors();
    EXPECT_TRUE(read_gro(dir.path() / "whole.gro").complete()) << rt->errors();
}

// show has nothing left to do without its window: it says why and ends with status 1.
TEST(Window, ShowEndsWhenTheDisplayGoesAway) {
    SKIP_WITHOUT_DISPLAY_TOOLS();
    if (std::system("command -v xdotool >/dev/null") != 0) {  // NOLINT(concurrency-mt-unsafe)
        GTEST_SKIP() << "xdotool is not installed (scripts/install-deps installs it)";
    }
    XDisplay x;
    ASSERT_TRUE(x.running());
    const TempDir dir;
    ASSERT_EQ(run_program("rt", {scene_path("twocubes"), "-n", "--output", "pic.gro"}, dir.path())
                  .exit_code,
              0);
    std::optional<SpawnedProgram> show;
    std::string earlier_errors;
    const Image8 shown = start_and_shoot(
        show, {"show", {"pic.gro"}, dir.path(), {x.name(), false}},
        [&] {  // its title changes with the pointer: it is found by the title's start
            const unsigned long id =
                std::strtoul(xdotool(x, "search --name '^show: pic.gro'").c_str(), nullptr, 10);
            return id == 0 ? Image8{} : screenshot_of(x.name(), id);
        },
        seconds(20), [](const Image8& s) { return s.width == 512; },
        [](SpawnedProgram& p) { return p.wait_for_exit(milliseconds(0)).has_value(); },
        earlier_errors);
    ASSERT_EQ(shown.width, 512) << "show opened no window: " << earlier_errors << show->errors();
    const std::string name = x.name();
    x.stop();
    EXPECT_EQ(show->wait_for_exit(seconds(20)), 1) << show->errors();
    EXPECT_NE(show->errors().find("show: lost the window: X display '" + name +
                                  "' closed the connection"),
              std::string::npos)
        << show->errors();
}

}  // namespace
}  // namespace rt::test
