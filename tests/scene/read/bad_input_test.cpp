// Every file in tests/data/scene/bad/ is a scene that must fail with exactly the message in the
// .expected file beside it. A line "flags: -M -Df ..." in the .scn (not a $ line, so the reader
// ignores it) chooses the dialect.
#include <algorithm>
#include <sstream>

#include "rt/scene/read/load_scene.h"

#include <gtest/gtest.h>

#include "reader_test_support.h"

namespace rt::test {
namespace {

namespace fs = std::filesystem;

fs::path bad_dir() {
    return scene_data() / "bad";
}

std::vector<std::string> bad_scenes() {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(bad_dir())) {
        if (entry.path().extension() == ".scn") {
            names.push_back(entry.path().stem().string());
        }
    }
    std::sort(names.begin(), names.end());
    return names;
}

ReaderDialect dialect_of(const std::string& scene_text) {
    ReaderDialect d;
    const std::size_t at = scene_text.find("flags:");
    if (at == std::string::npos) {
        return d;
    }
    std::istringstream flags(scene_text.substr(at + 6, scene_text.find('\n', at) - at - 6));
    for (std::string flag; flags >> flag;) {
        d.attributes_inline |= flag == "-Df" || flag == "-Of";
        d.no_power_fields |= flag == "-Dp" || flag == "-Of";
        d.smooth_shade_field |= flag == "-Po" || flag == "-Pt";
        d.marks |= flag == "-M";
        d.rgb_refraction |= flag == "-R";
        d.textures |= flag == "-V";
    }
    return d;
}

class BadScene : public ::testing::TestWithParam<std::string> {};

TEST_P(BadScene, FailsWithTheExpectedMessage) {
    const fs::path scene = bad_dir() / (GetParam() + ".scn");
    std::string expected = read_text(bad_dir() / (GetParam() + ".expected"));
    expected.erase(expected.find_last_not_of('\n') + 1);
    Diagnostics diagnostics;
    const std::string message =
        input_error([&] { load_scene(scene, dialect_of(read_text(scene)), diagnostics); });
    EXPECT_EQ(without(message, bad_dir().string() + "/"), expected);
}

INSTANTIATE_TEST_SUITE_P(Files, BadScene, ::testing::ValuesIn(bad_scenes()),
                         [](const auto& test) { return test.param; });

TEST(BadScenes, ThereAreMany) {
    EXPECT_GE(bad_scenes().size(), 40u);
}

}  // namespace
}  // namespace rt::test
