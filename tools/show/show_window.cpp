#include "show/show_window.h"

#include <iostream>
#include <memory>

#include "rt/image/film_summary.h"
#include "rt/image/image_writer.h"
#include "rt/image/png_format.h"
#include "rt/image/ppm_format.h"
#include "rt/window/picture_window.h"

#include <unistd.h>

namespace rt::show {

namespace {

Film film_of(const Image8& image) {
    Film film(image.width, image.height, {0, 0, image.width - 1, image.height - 1});
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const auto at = (static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) +
                             static_cast<std::size_t>(x)) *
                            3;
            film.set_pixel(
                x, y,
                {image.rgb[at] / 255.0, image.rgb[at + 1] / 255.0, image.rgb[at + 2] / 255.0});
        }
    }
    film.set_first_finished_row(0);  // a whole picture: the window draws finished rows only
    return film;
}

}  // namespace

Film read_shown_picture(const std::filesystem::path& path) {
    if (path.extension() == ".png") {
        return film_of(read_png(path));
    }
    if (path.extension() == ".ppm") {
        return film_of(read_ppm(path));
    }
    return read_linear_image(path);
}

int show_in_window(const Film& film, const std::string& name) {
    std::string why_not;
    WindowRequest request{
        "show: " + name, film.view_width(), film.view_height(), film.mapping, true, {}, {}};
    request.on_lost = [](const std::string& why) { std::cerr << "show: " << why << '\n'; };
    const std::unique_ptr<PictureWindow> window = open_picture_window(request, why_not);
    if (!window) {
        // Nothing to look at here: say what the picture is, and how to see it elsewhere.
        std::cout << film_summary(film);
        std::cerr << "show: " << why_not << "; use --output NAME.png to see the picture\n";
        return 0;
    }
    window->board().show_film(film);
    // On a terminal Enter ends it too; otherwise only closing the window (or a signal) does.
    wait_for_enter_or_close(*window, ::isatty(STDIN_FILENO) != 0 ? STDIN_FILENO : -1, {});
    return window->lost() ? 1 : 0;  // the picture was to be seen, and no one could see it
}

}  // namespace rt::show
