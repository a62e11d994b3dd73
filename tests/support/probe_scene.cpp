#include "support/probe_scene.h"

#include <iomanip>
#include <sstream>

#include <gtest/gtest.h>

#include "support/run_program.h"

namespace rt::test {

namespace {

// Every double written so that it reads back as the same double.
std::ostringstream exact_stream() {
    std::ostringstream out;
    out << std::setprecision(17);
    return out;
}

constexpr const char* kSquare =
    "4\n"
    "0 -1 -1 0\n"
    "1 1 -1 0\n"
    "2 1 1 0\n"
    "3 -1 1 0\n"
    "4\n"
    "0 0 1\n"
    "1 1 2\n"
    "2 2 3\n"
    "3 3 0\n"
    "1\n"
    "0 4 0 1 2 3 0 0 -1 0\n";

}  // namespace

std::string ProbeScene::scn_text() const {
    std::ostringstream out = exact_stream();
    out << "center lghtick sptncde octr graphmode normallength maxdepth maxdist\n"
        << "$ 0 " << lghtick << " 0 0 0 1 " << maxdepth << " 1\n"
        << "eyept & lookpt\n"
        << "$ " << eye[0] << ' ' << eye[1] << ' ' << eye[2] << ' ' << look[0] << ' ' << look[1]
        << ' ' << look[2] << '\n'
        << "screendist\n$ " << screen_distance << '\n'
        << "view angles x,y\n$ " << view_angle_x << ' ' << view_angle_y << '\n'
        << "sample resolution\n$ 1\n"
        << "viewarea in pixels x,y\n$ " << width << ' ' << height << '\n'
        << "output matrix boundaries\n$ 0 0 " << width - 1 << ' ' << height - 1 << '\n'
        << "name of file with list of attributes\n$ Attributes\n"
        << "entities, each one square\n$ " << squares.size() << '\n';
    for (std::size_t k = 0; k < squares.size(); ++k) {
        const ProbeSquare& q = squares[k];
        out << "$ 1 optical surface\n"
            << "$ " << k << ' ' << q.attribute << " 0 square " << q.scale << ' ' << q.centre[0]
            << ' ' << q.centre[1] << ' ' << q.centre[2] << " 0 " << q.turn_y_degrees << " 0\n";
    }
    return out.str();
}

std::string ProbeScene::attributes_text() const {
    std::ostringstream out = exact_stream();
    out << "attributes\n$ " << attributes.size() << '\n'
        << "r g b pow tpow e a d s t ref thetaR nR thetaT nT index\n";
    for (std::size_t k = 0; k < attributes.size(); ++k) {
        const ProbeAttribute& a = attributes[k];
        out << "$ " << a.colour[0] << ' ' << a.colour[1] << ' ' << a.colour[2] << ' ' << a.pow
            << " 2 " << a.e << ' ' << a.a << ' ' << a.d << ' ' << a.s << ' ' << a.t << ' '
            << a.refraction_index << " 0 1 0 1 " << k << '\n';
    }
    return out.str();
}

GroPixels render_probe(const TempDir& dir, const ProbeScene& scene,
                       const std::vector<std::string>& switches) {
    dir.write("probe.scn", scene.scn_text());
    dir.write("Attributes", scene.attributes_text());
    dir.write("square", kSquare);
    std::vector<std::string> args{"probe", "-Dd", "--quiet"};
    args.insert(args.end(), switches.begin(), switches.end());
    const ProgramResult r = run_program("rt", args, dir.path());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err, "") << "rt warned";
    return parse_gro(dir.path() / "probe.gro");
}

}  // namespace rt::test
