// The rendered picture: linear RGB per pixel of the output window, plus what made it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "rt/core/bounds.h"
#include "rt/core/rgb.h"

namespace rt {

/// How linear intensities become 8-bit display values (-m, -c; manual Appendix).
struct DisplayMapping {
    double multiplier = 1.0;  ///< -m: display value = intensity * 255 * multiplier
    bool clip = true;         ///< scale overflowing pixels down to keep their hue; -c turns it off
};

/// What rendered a film; written into the .gro header and shown by `show --info`.
struct FilmProvenance {
    std::string scene;     ///< the scene file as given
    std::string switches;  ///< the switches, space-separated
    std::string program;   ///< "rt 0.1.0"
    std::string created;   ///< UTC time, ISO 8601
    /// What --resume needs to render the same picture (empty in files written before it was
    /// recorded): the scene and switches as command-line words (rt's encoding), the seed of the
    /// random numbers, and a digest of the contents of every input file.
    std::string arguments;
    std::string seed;
    std::string inputs;
};

/// What a part file (`rt --tile I/N`) adds to its header; empty for a whole picture.
struct FilmPart {
    std::string part;  ///< "I N"
};

class Film {
public:
    Film() = default;
    /// view_width x view_height is the whole view area; only window's pixels are stored.
    Film(int view_width, int view_height, PixelRect window);

    int view_width() const { return view_width_; }
    int view_height() const { return view_height_; }
    const PixelRect& window() const { return window_; }
    int width() const { return window_.width(); }
    int height() const { return window_.height(); }

    /// x, y in view-area pixels (row 0 at the top), inside the window.
    Rgb pixel(int x, int y) const;
    void set_pixel(int x, int y, const Rgb& value);

    /// Rows are finished from the bottom up; rows y >= first_finished_row are done.
    int first_finished_row() const { return first_finished_row_; }
    void set_first_finished_row(int y) { first_finished_row_ = y; }
    bool complete() const { return first_finished_row_ <= window_.top; }

    DisplayMapping mapping;
    FilmProvenance provenance;
    FilmPart part;

    /// Throws rt::Error unless the window is non-empty and data() holds exactly its pixels; writers
    /// call it so a program bug never becomes a broken file.
    void check_consistent() const;

    /// Window pixels, row-major from the window's top row, three floats each.
    const std::vector<float>& data() const { return data_; }
    std::vector<float>& data() { return data_; }

private:
    int view_width_ = 0;
    int view_height_ = 0;
    PixelRect window_;
    int first_finished_row_ = 0;
    std::vector<float> data_;
};

}  // namespace rt
