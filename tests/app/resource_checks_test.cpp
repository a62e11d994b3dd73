// The checks before a render: the memory it needs, and room for its outputs.
#include <cstdint>
#include <filesystem>
#include <string>

#include "rt/app/memory_estimate.h"
#include "rt/app/output_checks.h"
#include "rt/core/error.h"

#include <gtest/gtest.h>

#include "support/scene_builder.h"
#include "support/temp_dir.h"

namespace rt {
namespace {

namespace fs = std::filesystem;

constexpr std::uint64_t kGiB = std::uint64_t{1} << 30;

std::uint64_t part_bytes(const std::vector<MemoryPart>& parts, const std::string& what) {
    for (const MemoryPart& part : parts) {
        if (part.what == what) {
            return part.bytes;
        }
    }
    ADD_FAILURE() << "no part named " << what;
    return 0;
}

TEST(MemoryEstimate, A16384SquareViewCountsItsFilmWindowAndPng) {
    test::SceneBuilder b;
    b.add_polygon({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}}, {0, 0, -1});
    b.scene().view.width = 16384;
    b.scene().view.height = 16384;
    Options options;
    options.outputs = {"picture.png"};
    const PixelRect window{0, 0, 16383, 16383};
    const std::vector<MemoryPart> parts = estimate_render_memory(b.scene(), options, window, true);
    // 2^28 pixels: 3 floats each in the film, twice 3 floats and twice a 4-byte texel in the
    // window (its picture, the wireframe's, the texture and the renderer's copy), and the PNG's
    // 8-bit picture and its encoding.
    EXPECT_EQ(part_bytes(parts, "the film"), 3 * kGiB);
    EXPECT_EQ(part_bytes(parts, "the window"), 8 * kGiB);
    EXPECT_EQ(part_bytes(parts, "the PNG"), 3 * kGiB / 2);
    // Only the window asked for is filmed: -L 16000 leaves 384 rows.
    const std::vector<MemoryPart> rows =
        estimate_render_memory(b.scene(), options, {0, 16000, 16383, 16383}, false);
    EXPECT_EQ(part_bytes(rows, "the film"), std::uint64_t{16384} * 384 * 12);
}

TEST(MemoryEstimate, ARefusalNamesTheFiguresAndTheWaysOut) {
    const std::vector<MemoryPart> parts = {{"the film", 3 * kGiB}, {"the PNG", kGiB / 2}};
    try {
        check_memory(parts, {2 * kGiB, "--max-memory"});
        FAIL() << "3.5 GiB fitted in 2";
    } catch (const UsageError& e) {
        const std::string text = e.what();
        EXPECT_NE(text.find("needs about 3.5 GiB (the film 3.0 GiB, the PNG 512 MiB)"),
                  std::string::npos)
            << text;
        EXPECT_NE(text.find("than the 2.0 GiB available (--max-memory)"), std::string::npos)
            << text;
        EXPECT_NE(text.find("-L"), std::string::npos) << text;
        EXPECT_NE(text.find("--max-memory GIB"), std::string::npos) << text;
        EXPECT_EQ(text.find("--no-window"), std::string::npos) << text;  // no window to leave
    }
    EXPECT_NO_THROW(check_memory(parts, {4 * kGiB, "--max-memory"}));
    // Where the window takes a part, rendering without it is one more way out.
    try {
        check_memory({{"the film", kGiB}, {"the window", 4 * kGiB}}, {2 * kGiB, "--max-memory"});
        FAIL() << "5 GiB fitted in 2";
    } catch (const UsageError& e) {
        EXPECT_NE(std::string(e.what()).find("render without the window (--no-window)"),
                  std::string::npos)
            << e.what();
    }
}

TEST(MemoryEstimate, TexturePicturesCountAndARefusalNamesThem) {
    test::SceneBuilder b;
    b.add_polygon({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}}, {0, 0, -1});
    b.scene().view.width = 16;
    b.scene().view.height = 16;
    // The size is all the estimate reads of a picture: no pixels are needed.
    b.scene().texture_images.push_back({16384, 16384, {}, "pmax.png"});
    Options options;
    const std::vector<MemoryPart> parts =
        estimate_render_memory(b.scene(), options, {0, 0, 15, 15}, false);
    EXPECT_EQ(part_bytes(parts, "the 16384 x 16384 texture picture 'pmax.png'"), 3 * kGiB / 4);
    try {
        check_memory(parts, {kGiB / 10, "--max-memory"});
        FAIL() << "768 MiB fitted in 102";
    } catch (const UsageError& e) {
        const std::string text = e.what();
        EXPECT_NE(text.find("(the 16384 x 16384 texture picture 'pmax.png' 768 MiB), more than "
                            "the 102 MiB available (--max-memory): use smaller texture pictures, "
                            "or set the limit with --max-memory GIB"),
                  std::string::npos)
            << text;
        EXPECT_EQ(text.find("-L"), std::string::npos) << text;  // no way out for a picture
    }
}

TEST(MemoryEstimate, LinuxSaysHowMuchIsAvailable) {
    if (!fs::exists("/proc/meminfo")) {
        GTEST_SKIP() << "no /proc/meminfo";
    }
    const std::optional<MemoryLimit> limit = available_memory();
    ASSERT_TRUE(limit.has_value());
    EXPECT_GT(limit->bytes, 0u);
    EXPECT_FALSE(limit->source.empty());
}

TEST(OutputChecks, SizeBoundsFollowTheFormat) {
    const PixelRect window{0, 0, 99, 49};  // 5000 pixels
    EXPECT_EQ(output_size_bound("a.gro", window), 60000u);
    EXPECT_EQ(output_size_bound("a.EXR", window), 60000u);
    EXPECT_EQ(output_size_bound("a.png", window), 15000u);
    EXPECT_EQ(output_size_bound("a.ppm", window), 15000u);
}

TEST(OutputChecks, AFullFolderIsRefusedWithTheFigures) {
    EXPECT_NO_THROW(check_free_space("out/a.gro", 1000, 1000));
    try {
        check_free_space("out/a.gro", 3 * kGiB, 0);
        FAIL() << "a full disk took the picture";
    } catch (const IoError& e) {
        EXPECT_STREQ(e.what(),
                     "cannot write out/a.gro: the picture takes up to 3.0 GiB, and its folder out "
                     "has 0 bytes free: free some space or write it elsewhere");
    }
}

TEST(OutputChecks, AWritableFolderPassesAndKeepsNoProbe) {
    const test::TempDir dir;
    EXPECT_NO_THROW(check_output_folder(dir.path() / "a.png"));
    EXPECT_TRUE(fs::is_empty(dir.path()));
}

TEST(OutputChecks, AFileWhereTheFolderShouldBeIsNamed) {
    const test::TempDir dir;
    dir.write("afile", "");
    try {
        check_output_folder(dir.path() / "afile" / "a.png");
        FAIL() << "wrote into a file";
    } catch (const IoError& e) {
        EXPECT_NE(std::string(e.what()).find("afile is not a folder"), std::string::npos)
            << e.what();
    }
}

TEST(OutputChecks, ADeviceIsNotReplaced) {
    const test::TempDir dir;
    fs::create_symlink("/dev/null", dir.path() / "null.png");
    try {
        check_output_folder(dir.path() / "null.png");
        FAIL() << "a device was taken for a picture";
    } catch (const IoError& e) {
        EXPECT_NE(std::string(e.what()).find("is a device, a pipe or a socket"), std::string::npos)
            << e.what();
    }
}

// /proc takes no new files, even from root (for whom access() says it is writable).
TEST(OutputChecks, AFolderThatTakesNoFilesIsRefusedEvenForRoot) {
    if (!fs::is_directory("/proc/self")) {
        GTEST_SKIP() << "no /proc";
    }
    try {
        check_output_folder("/proc/rt-picture.png");
        FAIL() << "/proc took a picture";
    } catch (const IoError& e) {
        EXPECT_NE(std::string(e.what()).find("cannot write /proc/rt-picture.png: "),
                  std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace rt
