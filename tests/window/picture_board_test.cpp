// The board between the threads that fill a window and the window's own thread: it maps only the
// rows that changed, places a film's finished rows, and hands a film over whole, never half copied.
#include "rt/window/picture_board.h"

#include <atomic>
#include <cstdint>
#include <stdexcept>
#include <thread>
#include <vector>

#include "rt/image/display_mapping.h"

#include <gtest/gtest.h>

namespace rt {
namespace {

// A film over the whole view with every pixel (v, v, v), its rows from `first_finished` down
// finished.
Film grey_film(int width, int height, float v, int first_finished) {
    Film film(width, height, PixelRect{0, 0, width - 1, height - 1});
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            film.set_pixel(x, y, Rgb{v, v, v});
        }
    }
    film.set_first_finished_row(first_finished);
    return film;
}

std::uint8_t display_value(const std::vector<std::uint8_t>& rgb, int width, int x, int y) {
    return rgb[(static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                static_cast<std::size_t>(x)) *
               3];
}

TEST(PictureBoard, FirstUpdateMapsEveryRowThenOnlyTheChangedOnes) {
    PictureBoard board(4, 6, DisplayMapping{});
    std::vector<std::uint8_t> rgb;
    PictureBoard::Rows rows = board.update(rgb);
    EXPECT_EQ(rows.top, 0);
    EXPECT_EQ(rows.bottom, 5);
    ASSERT_EQ(rgb.size(), 4U * 6U * 3U);
    rows = board.update(rgb);
    EXPECT_GT(rows.top, rows.bottom) << "nothing changed";

    const std::vector<float> white(4 * 3, 1.0F);
    board.show_row(0, 4, white);
    board.show_row(0, 2, white);
    rows = board.update(rgb);
    EXPECT_EQ(rows.top, 2);
    EXPECT_EQ(rows.bottom, 4);
    EXPECT_EQ(display_value(rgb, 4, 3, 4), 255);
    EXPECT_EQ(display_value(rgb, 4, 3, 3), 0);

    const DisplayMapping half{0.5, true};
    board.set_mapping(half);
    rows = board.update(rgb);
    EXPECT_EQ(rows.top, 0) << "a new mapping redraws everything";
    EXPECT_EQ(rows.bottom, 5);
    EXPECT_EQ(display_value(rgb, 4, 0, 2), to_display(Rgb{1.0, 1.0, 1.0}, half)[0]);
    EXPECT_LT(display_value(rgb, 4, 0, 2), 255);
}

TEST(PictureBoard, ShowsOnlyAFilmsFinishedRows) {
    PictureBoard board(3, 5, DisplayMapping{});
    std::vector<std::uint8_t> rgb;
    board.update(rgb);
    board.show_film(grey_film(3, 5, 1.0F, 3));
    const PictureBoard::Rows rows = board.update(rgb);
    EXPECT_EQ(rows.top, 3);
    EXPECT_EQ(rows.bottom, 4);
    EXPECT_EQ(display_value(rgb, 3, 1, 3), 255);
    EXPECT_EQ(display_value(rgb, 3, 1, 2), 0);
    EXPECT_FLOAT_EQ(board.pixel(2, 4).g, 1.0F);
}

TEST(PictureBoard, RefusesARowOutsideThePicture) {
    PictureBoard board(3, 2, DisplayMapping{});
    const std::vector<float> row(3 * 3, 1.0F);
    EXPECT_THROW(board.show_row(0, 2, row), std::out_of_range);
    EXPECT_THROW(board.show_row(1, 0, row), std::out_of_range);
    EXPECT_THROW(board.show_row(0, -1, row), std::out_of_range);
}

// The window's thread draws whatever update() hands it: a film (a wireframe) shown while it draws
// must reach it whole, or the window shows its top rows over black for a frame.
TEST(PictureBoard, AFilmReachesTheWindowWhole) {
    constexpr int kWidth = 256;
    constexpr int kHeight = 512;
    const Film film = grey_film(kWidth, kHeight, 1.0F, 0);
    for (int round = 0; round < 20; ++round) {
        PictureBoard board(kWidth, kHeight, DisplayMapping{});
        std::vector<std::uint8_t> rgb;
        board.update(rgb);  // the first frame: all black
        std::atomic<bool> started{false};
        std::thread writer([&] {
            started = true;
            board.show_film(film);
        });
        while (!started) {
            std::this_thread::yield();
        }
        PictureBoard::Rows rows;
        do {
            rows = board.update(rgb);
        } while (rows.top > rows.bottom);
        writer.join();
        EXPECT_EQ(rows.top, 0);
        ASSERT_EQ(rows.bottom, kHeight - 1) << "round " << round << ": a frame of part of the film";
        EXPECT_EQ(display_value(rgb, kWidth, kWidth - 1, kHeight - 1), 255);
    }
}

}  // namespace
}  // namespace rt
