// Views for the methods that keep something for eye rays alone (the z-buffer's item buffer, exit
// culling's coverage of the view), which must answer every eye ray as brute force does: the
// manual's scene as it views it, and from close by, far off, straight down, very wide and on the
// floor; from inside a box with the screen cutting its walls; inside a sphere; amid soups; in the
// plane of a polygon. And the sample positions within a pixel that find the edges.
#pragma once

#include <string>
#include <vector>

#include "rt/geometry/camera.h"
#include "rt/scene/scene.h"

#include "accel/accel_test_scenes.h"

namespace rt::test {

struct CameraCase {
    Vec3 eye;
    Vec3 look;
    double screen_distance = 1.0;
    double angle_x = 40.0;
    double angle_y = 30.0;
    int width = 48;
    int height = 36;
};

inline void set_view(Scene& scene, const CameraCase& c) {
    scene.view.eye = c.eye;
    scene.view.look = c.look;
    scene.view.screen_distance = c.screen_distance;
    scene.view.view_angle_x_degrees = c.angle_x;
    scene.view.view_angle_y_degrees = c.angle_y;
    scene.view.width = c.width;
    scene.view.height = c.height;
}

/// Sample positions within a pixel: its corner, edge midpoints, centre, and points a hair inside
/// the far edges.
inline constexpr double kPixelOffsets[] = {0.0, 0.5, 1e-12, 1.0 - 1e-12};

/// Calls visit(px, py) for every sample position of every `step`-th pixel, and of the view
/// area's far edges.
template <class Visit>
void for_each_view_sample(const Camera& view, int step, Visit&& visit) {
    for (int y = 0; y <= view.height; y += step) {
        for (int x = 0; x <= view.width; x += step) {
            for (const double dx : kPixelOffsets) {
                for (const double dy : kPixelOffsets) {
                    visit(std::min(x + dx, static_cast<double>(view.width)),
                          std::min(y + dy, static_cast<double>(view.height)));
                }
            }
        }
    }
}

struct ViewedScene {
    std::string name;
    Scene scene;
    int step = 1;  ///< every step-th pixel is enough
};

inline std::vector<std::string> viewed_scene_names() {
    return {"manual",
            "close",
            "down",
            "straight_down",
            "very_wide",
            "on_the_floor",
            "far_off",
            "inside_box_near_screen",
            "inside_box",
            "inside_box_far_screen",
            "inside_sphere",
            "amid_soup",
            "amid_warped_soup",
            "floor_level"};
}

// The first box of make_boxes(13, 12): its walls are polygons 1 to 6.
inline Vec3 first_box_centre(const Scene& scene) {
    Vec3 lo = scene.corner_position(scene.polygons[1], 0);
    Vec3 hi = lo;
    for (std::uint32_t k = 0; k < 24; ++k) {
        const Polygon& p = scene.polygons[1 + k / 4];
        lo = min_components(lo, scene.corner_position(p, k % 4));
        hi = max_components(hi, scene.corner_position(p, k % 4));
    }
    return (lo + hi) * 0.5;
}

inline ViewedScene viewed_scene(const std::string& name) {
    const auto twocubes = [&](const CameraCase& c) {
        ViewedScene v{name, load_twocubes()};
        set_view(v.scene, c);
        return v;
    };
    const auto inside_box = [&](double screen) {
        ViewedScene v{name, make_boxes(13, 12)};
        const Vec3 centre = first_box_centre(v.scene);
        set_view(v.scene, {centre, centre + Vec3{1, 0.2, 0.3}, screen, 100.0, 80.0});
        return v;
    };
    if (name == "manual") {
        return {name, load_twocubes(), 5};
    }
    if (name == "close") {
        return twocubes({{3, 1, -6}, {0, 0, 0}, 2.0, 90.0, 70.0});
    }
    if (name == "down") {
        return twocubes({{0.5, 30, 0.5}, {0.5, 0, 0.5}, 5.0, 60.0, 60.0});
    }
    if (name == "straight_down") {
        return twocubes({{0, 30, 0}, {0, 0, 0}, 5.0, 60.0, 60.0});
    }
    if (name == "very_wide") {
        return twocubes({{1, 0, -4}, {0, 0, 0}, 0.5, 170.0, 160.0});
    }
    if (name == "on_the_floor") {
        return twocubes({{-1, -3, -9}, {0, -3, 0}, 1.0, 60.0, 40.0});
    }
    if (name == "far_off") {
        return twocubes({{-300, 40, -120}, {0, 0, 0}, 2.0, 50.0, 40.0});
    }
    // The eye inside the first box, with screen distances that cut through its walls.
    if (name == "inside_box_near_screen") {
        return inside_box(0.05);
    }
    if (name == "inside_box") {
        return inside_box(0.4);
    }
    if (name == "inside_box_far_screen") {
        return inside_box(1.5);
    }
    ViewedScene v{name, Scene{}};
    if (name == "inside_sphere") {
        v.scene = make_sphere({0, 0, 0}, 3.0, 10, 16, true);
        set_view(v.scene, {{0.5, 0.2, -1}, {0, 0, 1}, 0.7, 120.0, 100.0});
    } else if (name == "amid_soup") {
        v.scene = make_soup(17, 200);
        set_view(v.scene, {{0, 0, 0}, {1, 2, 3}, 1.0, 70.0, 50.0});
    } else if (name == "amid_warped_soup") {
        v.scene = make_soup(18, 100, true);
        set_view(v.scene, {{0.5, 0, 0}, {1, -2, 3}, 3.0, 70.0, 50.0});
    } else if (name == "floor_level") {
        // Seen exactly edge-on, the floor's reported hits come from the grazing branch.
        v.scene = make_boxes(19, 4);
        set_view(v.scene, {{-25, 0, -25}, {0, 0, 0}, 1.0, 60.0, 40.0});
    }
    return v;
}

}  // namespace rt::test
