// Small scenes for pixel probes (tests/integration/pixel_probes_*_test.cpp): squares with chosen
// attributes in front of a pinhole camera, written as the manual's files (a .scn, an Attributes
// file, one filetype-0 optical surface) and rendered by the real rt program.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "support/hand_readers.h"
#include "support/temp_dir.h"

namespace rt::test {

using Triple = std::array<double, 3>;

/// One line of the Attributes file (manual 2.3). The distributed-ray cones are 0: single rays.
struct ProbeAttribute {
    Triple colour{};
    double e = 0.0;  ///< emitted
    double a = 0.0;  ///< ambient
    double d = 0.0;  ///< diffuse
    double s = 0.0;  ///< specular (highlight and mirror)
    double t = 0.0;  ///< transmitted
    double pow = 2.0;
    double refraction_index = 1.0;
};

/// The square file: corners (+-1, +-1, 0), outward normal (0, 0, -1), placed by the .scn line as
/// scale, then a turn of `turn_y_degrees` about y, then a move to `centre` (docs/formats.md).
struct ProbeSquare {
    int attribute = 0;  ///< index into ProbeScene::attributes
    double scale = 1.0;
    Triple centre{};
    double turn_y_degrees = 0.0;
};

struct ProbeScene {
    int lghtick = 0;   ///< 0: no shadow feelers; 1: emitters' corners; 2: their centres
    int maxdepth = 3;  ///< the eye ray is depth 1
    Triple eye{0.0, 0.0, -20.0};
    Triple look{0.0, 0.0, 0.0};
    double screen_distance = 5.0;
    double view_angle_x = 40.0;  ///< degrees, the full angle
    double view_angle_y = 30.0;
    int width = 7;  ///< view area in pixels, all rendered
    int height = 5;
    std::vector<ProbeAttribute> attributes;
    std::vector<ProbeSquare> squares;

    /// The .scn text (sample resolution 1, the whole view as the window).
    std::string scn_text() const;
    std::string attributes_text() const;
};

/// Writes probe.scn, Attributes and square into dir, runs `rt probe -Dd --quiet switches...`
/// there and returns probe.gro as written (parsed with parse_gro). A failed run fails the test.
GroPixels render_probe(const TempDir& dir, const ProbeScene& scene,
                       const std::vector<std::string>& switches = {});

}  // namespace rt::test
