#include "rt/image/film_summary.h"

#include <fmt/format.h>

namespace rt {

namespace {

std::string or_unknown(const std::string& text) {
    return text.empty() ? "(not recorded)" : text;
}

}  // namespace

std::string header_summary(const GroHeader& header) {
    const PixelRect& w = header.window;
    const int rows_done = w.bottom + 1 - std::max(header.first_finished_row, w.top);
    const bool complete = header.first_finished_row <= w.top;
    std::string text;
    text += fmt::format("size      {} x {} pixels (the view area)\n", header.view_width,
                        header.view_height);
    text += fmt::format("window    {} {} {} {} (left top right bottom: {} x {} pixels)\n", w.left,
                        w.top, w.right, w.bottom, w.width(), w.height());
    text += fmt::format("rows      {} of {} finished{}\n", rows_done, w.height(),
                        complete ? "" : " (from the bottom up)");
    text += fmt::format("display   multiplier {}, clipping {}\n", header.mapping.multiplier,
                        header.mapping.clip ? "on" : "off");
    text += fmt::format("scene     {}\n", or_unknown(header.provenance.scene));
    text += fmt::format("switches  {}\n",
                        header.provenance.switches.empty() ? "(none)" : header.provenance.switches);
    text += fmt::format("program   {}\n", or_unknown(header.provenance.program));
    text += fmt::format("created   {}\n", or_unknown(header.provenance.created));
    const FilmProvenance& p = header.provenance;
    if (!p.arguments.empty()) {
        text += fmt::format("seed      {}\n", p.seed);
        text += fmt::format("inputs    {}\n", p.inputs);
    }
    if (!header.part.part.empty()) {
        text += fmt::format("part      {} (for merge)\n", header.part.part);
    }
    if (!complete) {
        text += p.arguments.empty()
                    ? "resume    not possible: the file does not record what rendered it\n"
                    : "resume    rt --resume FILE.gro renders the missing rows\n";
    }
    return text;
}

std::string film_summary(const Film& film) {
    GroHeader header;
    header.view_width = film.view_width();
    header.view_height = film.view_height();
    header.window = film.window();
    header.first_finished_row = film.first_finished_row();
    header.mapping = film.mapping;
    header.provenance = film.provenance;
    header.part = film.part;
    return header_summary(header);
}

}  // namespace rt
