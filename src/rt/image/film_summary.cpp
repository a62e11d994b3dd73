#include "rt/image/film_summary.h"

#include <fmt/format.h>

namespace rt {

namespace {

std::string or_unknown(const std::string& text) {
    return text.empty() ? "(not recorded)" : text;
}

}  // namespace

std::string film_summary(const Film& film) {
    const PixelRect& w = film.window();
    const int rows_done = w.bottom + 1 - std::max(film.first_finished_row(), w.top);
    std::string text;
    text += fmt::format("size      {} x {} pixels (the view area)\n", film.view_width(),
                        film.view_height());
    text += fmt::format("window    {} {} {} {} (left top right bottom: {} x {} pixels)\n", w.left,
                        w.top, w.right, w.bottom, w.width(), w.height());
    text += fmt::format("rows      {} of {} finished{}\n", rows_done, w.height(),
                        film.complete() ? "" : " (from the bottom up)");
    text += fmt::format("display   multiplier {}, clipping {}\n", film.mapping.multiplier,
                        film.mapping.clip ? "on" : "off");
    text += fmt::format("scene     {}\n", or_unknown(film.provenance.scene));
    text += fmt::format("switches  {}\n",
                        film.provenance.switches.empty() ? "(none)" : film.provenance.switches);
    text += fmt::format("program   {}\n", or_unknown(film.provenance.program));
    text += fmt::format("created   {}\n", or_unknown(film.provenance.created));
    return text;
}

}  // namespace rt
