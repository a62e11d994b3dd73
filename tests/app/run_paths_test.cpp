// Which file a SCENE argument names, and where the default .gro goes.
#include <filesystem>

#include "rt/app/run.h"

#include <gtest/gtest.h>

#include "support/temp_dir.h"

namespace rt {
namespace {

namespace fs = std::filesystem;

TEST(ResolveScenePath, NameEndingInScnIsTakenAsIs) {
    const test::TempDir dir;
    EXPECT_EQ(resolve_scene_path((dir.path() / "missing.scn").string()),
              dir.path() / "missing.scn");
}

TEST(ResolveScenePath, ScnSuffixIsAddedWhenThatFileExists) {
    const test::TempDir dir;
    dir.write("cube.scn", "");
    dir.write("cube", "");  // a file without the suffix loses to the .scn beside it
    EXPECT_EQ(resolve_scene_path((dir.path() / "cube").string()), dir.path() / "cube.scn");
}

TEST(ResolveScenePath, AFileWithoutSuffixIsTakenWhenNoScnExists) {
    const test::TempDir dir;
    dir.write("scene.txt", "");
    EXPECT_EQ(resolve_scene_path((dir.path() / "scene.txt").string()), dir.path() / "scene.txt");
}

TEST(ResolveScenePath, NothingThereNamesTheUsualSpelling) {
    // So that the reader's "cannot open" names SCENE.scn; a folder is not a scene file either.
    const test::TempDir dir;
    fs::create_directory(dir.path() / "folder");
    EXPECT_EQ(resolve_scene_path((dir.path() / "nothing").string()), dir.path() / "nothing.scn");
    EXPECT_EQ(resolve_scene_path((dir.path() / "folder").string()), dir.path() / "folder.scn");
}

TEST(DefaultGroPath, IsTheScenesNameWithGroInTheCurrentFolder) {
    EXPECT_EQ(default_gro_path("scenes/twocubes.scn"), fs::path("twocubes.gro"));
    EXPECT_EQ(default_gro_path("scenes/twocubes"), fs::path("twocubes.gro"));
    EXPECT_EQ(default_gro_path("/abs/a.b"), fs::path("a.b.gro"));
}

}  // namespace
}  // namespace rt
