#include "picture_regions.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "rt/image/gro_format.h"
#include "rt/image/ppm_format.h"

#include "support/run_program.h"

namespace rt::test {

namespace {

namespace fs = std::filesystem;

constexpr double kLevels = 255.0;       // an intensity of 1 is 255 display levels
constexpr double kChangedLevel = 0.5;   // a pixel "changed" when some channel moved this much
constexpr double kTouchedLevel = 1e-3;  // ... and was "touched" when it moved at all (float32)

double display_sum(const Image8& image, int x, int y) {
    const std::size_t at = (static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) +
                            static_cast<std::size_t>(x)) *
                           3;
    return static_cast<double>(image.rgb[at]) + static_cast<double>(image.rgb[at + 1]) +
           static_cast<double>(image.rgb[at + 2]);
}

int display_distance(const Image8& a, const Image8& b, int x, int y) {
    const std::size_t at = (static_cast<std::size_t>(y) * static_cast<std::size_t>(a.width) +
                            static_cast<std::size_t>(x)) *
                           3;
    int largest = 0;
    for (std::size_t c = 0; c < 3; ++c) {
        largest = std::max(largest, std::abs(int{a.rgb[at + c]} - int{b.rgb[at + c]}));
    }
    return largest;
}

}  // namespace

std::optional<Picture> render_picture(const fs::path& scene,
                                      const std::vector<std::string>& switches,
                                      const fs::path& folder, std::string& error) {
    // No -n, which -O1 would refuse: the .gro goes where rt puts it, in the current folder.
    // Not --quiet either: the rows of the debugging switches read what rt prints. One thread
    // (unless the switches say otherwise), as the tests run side by side.
    std::vector<std::string> args{scene.string(), "--output", "out.ppm"};
    if (std::find(switches.begin(), switches.end(), "--threads") == switches.end()) {
        args.insert(args.end(), {"--threads", "1"});
    }
    args.insert(args.end(), switches.begin(), switches.end());
    const fs::path gro = folder / scene.filename().replace_extension(".gro");
    fs::remove(gro);
    fs::remove(folder / "out.ppm");
    const ProgramResult r = run_program("rt", args, folder);
    if (r.exit_code != 0) {
        error = r.err;
        return std::nullopt;
    }
    const Film film = read_gro(gro);
    Picture picture;
    picture.width = film.width();
    picture.height = film.height();
    picture.levels.reserve(film.data().size() / 3);
    for (std::size_t k = 0; k + 2 < film.data().size(); k += 3) {
        picture.levels.push_back(Rgb{film.data()[k], film.data()[k + 1], film.data()[k + 2]} *
                                 kLevels);
    }
    picture.display = read_ppm(folder / "out.ppm");
    picture.output = r.out + r.err;
    return picture;
}

RegionChange measure_change(const Picture& base, const Picture& picture, const Region& region) {
    const auto inside = [&](const Picture& p) {
        return region.left >= 0 && region.top >= 0 && region.left <= region.right &&
               region.top <= region.bottom && region.right < p.width && region.bottom < p.height;
    };
    if (!inside(base) || !inside(picture)) {
        throw std::out_of_range("region " + std::string(region.name) +
                                " is not inside the picture");
    }
    RegionChange change;
    double base_display = 0.0;
    double display = 0.0;
    int changed = 0;
    int touched = 0;
    int display_changed = 0;
    for (int y = region.top; y <= region.bottom; ++y) {
        for (int x = region.left; x <= region.right; ++x) {
            const std::size_t at =
                static_cast<std::size_t>(y) * static_cast<std::size_t>(base.width) +
                static_cast<std::size_t>(x);
            const Rgb d = picture.levels[at] + base.levels[at] * -1.0;
            change.mean_difference += d;
            const double moved = std::max({std::fabs(d.r), std::fabs(d.g), std::fabs(d.b)});
            changed += moved > kChangedLevel;
            touched += moved > kTouchedLevel;
            base_display += display_sum(base.display, x, y);
            display += display_sum(picture.display, x, y);
            display_changed += display_distance(base.display, picture.display, x, y) > 1;
        }
    }
    const double count =
        static_cast<double>((region.right - region.left + 1) * (region.bottom - region.top + 1));
    change.mean_difference *= 1.0 / count;
    change.changed_fraction = changed / count;
    change.touched_fraction = touched / count;
    change.display_changed = display_changed / count;
    change.display_ratio = base_display > 0.0 ? display / base_display : 1.0;
    return change;
}

}  // namespace rt::test
