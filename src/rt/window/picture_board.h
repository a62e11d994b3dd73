// What a window shows: the picture's linear intensities over the whole view area, shared between
// the threads that fill it (the renderer's rows, a picture read from a file) and the window's own
// thread, which draws it at display rate. Writers hold the lock only to copy rows in.
#pragma once

#include <cstdint>
#include <mutex>
#include <span>
#include <vector>

#include "rt/core/rgb.h"
#include "rt/image/film.h"

namespace rt {

class PictureBoard {
public:
    PictureBoard(int view_width, int view_height, DisplayMapping mapping);

    int width() const { return width_; }
    int height() const { return height_; }

    /// The film's finished rows (all of them for a wireframe or a picture read from a file), at
    /// their place in the view area.
    void show_film(const Film& film);
    /// One row of `width` pixels (three floats each) starting at view pixel (left, y).
    void show_row(int left, int y, std::span<const float> pixels);

    DisplayMapping mapping() const;
    void set_mapping(const DisplayMapping& mapping);
    /// The linear intensity at view pixel (x, y), which must lie in the view.
    Rgb pixel(int x, int y) const;

    /// Rows [top, bottom] of the view changed since the last copy; empty when top > bottom.
    struct Rows {
        int top = 0;
        int bottom = -1;
    };
    /// Brings `rgb` (8-bit RGB display values, row by row from the top, sized here) up to date:
    /// maps only the rows changed since the last call (all of them on the first, or after a new
    /// mapping), and says which.
    Rows update(std::vector<std::uint8_t>& rgb);

private:
    void copy_row(int left, int y, std::span<const float> pixels);  // the lock is held

    int width_;
    int height_;
    mutable std::mutex mutex_;
    DisplayMapping mapping_;
    std::vector<float> linear_;  // width x height x 3, row 0 at the top
    Rows dirty_;                 // rows changed since the last update()
};

}  // namespace rt
