// The window a run draws: the scene's, cut at the start line (-L), or refused above its top.
#include "rt/render/film_window.h"

#include "rt/core/error.h"

#include <gtest/gtest.h>

namespace rt {
namespace {

constexpr PixelRect kSceneWindow{10, 20, 300, 200};

TEST(FilmWindow, IsTheScenesWindowWithoutAStartLine) {
    EXPECT_EQ(film_window(kSceneWindow, std::nullopt), kSceneWindow);
}

TEST(FilmWindow, KeepsTheRowsFromTheStartLineUp) {
    EXPECT_EQ(film_window(kSceneWindow, 150), (PixelRect{10, 20, 300, 150}));
    EXPECT_EQ(film_window(kSceneWindow, 20), (PixelRect{10, 20, 300, 20}));
}

TEST(FilmWindow, AStartLineBelowTheWindowCutsNothing) {
    EXPECT_EQ(film_window(kSceneWindow, 500), kSceneWindow);
}

TEST(FilmWindow, RefusesAStartLineAboveTheTopRowNamingTheSetting) {
    try {
        (void)film_window(kSceneWindow, 19);
        FAIL() << "a start line above the window was accepted";
    } catch (const SettingError& error) {
        EXPECT_EQ(error.setting(), "start line");
        EXPECT_STREQ(error.what(), "the start line 19 is above the window's top row 20");
    }
}

}  // namespace
}  // namespace rt
