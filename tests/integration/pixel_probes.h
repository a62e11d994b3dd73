// The pixel probes' own arithmetic: vectors, the camera of the manual and docs/rendering.md, the
// placed squares of a ProbeScene, and which square a ray meets. Written here from the documents,
// never calling the renderer, so that a probe and rt can only agree by both being right.
#pragma once

#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "support/hand_readers.h"
#include "support/probe_scene.h"

namespace rt::test::probe {

struct V {
    double x = 0.0;
    double y = 0.0;
    double z = 0.0;
};

inline V operator+(V a, V b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline V operator-(V a, V b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline V operator*(V a, double k) {
    return {a.x * k, a.y * k, a.z * k};
}
inline double dot(V a, V b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline V cross(V a, V b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double length(V a) {
    return std::sqrt(dot(a, a));
}
inline V unit(V a) {
    return a * (1.0 / length(a));
}
inline V from(const Triple& t) {
    return {t[0], t[1], t[2]};
}

/// An RGB intensity, with the products the illumination formulas need.
struct Colour {
    double r = 0.0;
    double g = 0.0;
    double b = 0.0;
};
inline Colour operator+(Colour p, Colour q) {
    return {p.r + q.r, p.g + q.g, p.b + q.b};
}
inline Colour operator*(Colour p, Colour q) {
    return {p.r * q.r, p.g * q.g, p.b * q.b};
}
inline Colour operator*(Colour p, double k) {
    return {p.r * k, p.g * k, p.b * k};
}
inline Colour colour_of(const ProbeAttribute& a) {
    return {a.colour[0], a.colour[1], a.colour[2]};
}

/// The manual's attenuation (Appendix -A): intensity divided by dist/d + c.
inline double attenuation(double distance, double d = 200.0, double c = 1.0) {
    return 1.0 / (distance / d + c);
}

// What a run's switches change in the formulas (manual Appendix -A, -Da, -Dl, -Db, -Dt).
struct Switches {
    std::vector<std::string> words;  ///< as given to rt
    double att_d = 200.0;            ///< -A d,c (default 200, 1)
    double att_c = 1.0;
    bool eye_rays_attenuate = true;  ///< off with -Da
    bool feelers_attenuate = true;   ///< off with -Dl
    bool back_emits = true;          ///< off with -Db
    bool feelers_pass_glass = true;  ///< off with -Dt

    explicit Switches(std::vector<std::string> given = {}) : words(std::move(given)) {
        for (const std::string& w : words) {
            if (w.starts_with("-A")) {
                const std::size_t comma = w.find(',');
                att_d = std::stod(w.substr(2, comma - 2));
                att_c = std::stod(w.substr(comma + 1));
            }
            eye_rays_attenuate = eye_rays_attenuate && w != "-Da";
            feelers_attenuate = feelers_attenuate && w != "-Dl";
            back_emits = back_emits && w != "-Db";
            feelers_pass_glass = feelers_pass_glass && w != "-Dt";
        }
    }
    std::string name() const {
        std::string joined = "switches:";
        for (const std::string& w : words) {
            joined += " " + w;
        }
        return joined;
    }
};

inline double ray_factor(const Switches& run, double distance) {
    return run.eye_rays_attenuate ? attenuation(distance, run.att_d, run.att_c) : 1.0;
}

inline double feeler_factor(const Switches& run, double distance) {
    return run.feelers_attenuate ? attenuation(distance, run.att_d, run.att_c) : 1.0;
}

struct Ray {
    V origin;
    V direction;  ///< unit
};

/// The eye ray through the centre of pixel (x, y) (sample resolution 1): from the eye through the
/// screen, starting on the screen. +y is up, +x right with z into the screen (left-handed, so
/// right = up x forward); the angles are the full angles the screen subtends; row 0 is the top.
inline Ray pixel_ray(const ProbeScene& s, int x, int y) {
    const V eye = from(s.eye);
    const V forward = unit(from(s.look) - eye);
    const V right = unit(cross(V{0.0, 1.0, 0.0}, forward));
    const V up = cross(forward, right);
    const double degrees = std::numbers::pi / 180.0;
    const double half_width = s.screen_distance * std::tan(s.view_angle_x * degrees / 2.0);
    const double half_height = s.screen_distance * std::tan(s.view_angle_y * degrees / 2.0);
    const double across = ((x + 0.5) / s.width * 2.0 - 1.0) * half_width;
    const double down = ((y + 0.5) / s.height * 2.0 - 1.0) * half_height;
    const V on_screen = eye + forward * s.screen_distance + right * across - up * down;
    return {on_screen, unit(on_screen - eye)};
}

/// A square of the scene in the world: centre, half-axes u and v, outward normal.
struct Placed {
    V centre;
    V u;
    V v;
    V normal;
};

/// The square file's corners (+-1, +-1, 0) and normal (0, 0, -1), scaled, turned about y (a
/// positive angle turns +z toward +x: x' = x cos + z sin, z' = -x sin + z cos) and moved.
inline Placed place(const ProbeSquare& q) {
    const double angle = q.turn_y_degrees * std::numbers::pi / 180.0;
    const auto turn = [angle](V p) {
        return V{p.x * std::cos(angle) + p.z * std::sin(angle), p.y,
                 -p.x * std::sin(angle) + p.z * std::cos(angle)};
    };
    return {from(q.centre), turn({q.scale, 0.0, 0.0}), {0.0, q.scale, 0.0}, turn({0.0, 0.0, -1.0})};
}

/// Where a line origin + t * direction (t > 0) meets a square's plane, and how far inside the
/// square that is: 1 at the centre, 0 on an edge, negative outside (in units of the half-side).
struct Crossing {
    double t = 0.0;
    V point;
    double inside = -1.0;
};

inline std::optional<Crossing> cross_plane(V origin, V direction, const Placed& q) {
    const double facing = dot(direction, q.normal);
    if (std::fabs(facing) < 1e-12) {
        return std::nullopt;
    }
    const double t = dot(q.centre - origin, q.normal) / facing;
    if (!(t > 1e-9)) {
        return std::nullopt;
    }
    const V p = origin + direction * t;
    const double su = std::fabs(dot(p - q.centre, q.u)) / dot(q.u, q.u);
    const double sv = std::fabs(dot(p - q.centre, q.v)) / dot(q.v, q.v);
    return Crossing{t, p, 1.0 - std::fmax(su, sv)};
}

/// Closer to an edge than this (relative to the half-side) is too close to call.
constexpr double kEdgeMargin = 1e-3;

/// Not the index of a square: a ray or feeler met none.
constexpr int kNoSquare = -1;
/// Not the index of a square: a feeler passes too close to an edge to call what it meets.
constexpr int kTooCloseToCall = -2;

/// The first square a ray meets, leaving out square `leaving` (the one it starts on).
struct FirstHit {
    int square = kNoSquare;
    Crossing at;
    bool clear = true;  ///< false if an edge passes too close to call what the ray meets
};

inline FirstHit first_hit(const ProbeScene& s, const Ray& ray, int leaving = kNoSquare) {
    FirstHit best;
    best.at.t = std::numeric_limits<double>::infinity();
    for (int k = 0; k < static_cast<int>(s.squares.size()); ++k) {
        if (k == leaving) {
            continue;
        }
        const std::optional<Crossing> c =
            cross_plane(ray.origin, ray.direction, place(s.squares[k]));
        if (c && c->inside > 0.0 && c->t < best.at.t) {
            best.square = k;
            best.at = *c;
        }
    }
    // Any edge near the ray before the hit makes the pixel ambiguous.
    for (int k = 0; k < static_cast<int>(s.squares.size()); ++k) {
        const std::optional<Crossing> c =
            k == leaving ? std::nullopt
                         : cross_plane(ray.origin, ray.direction, place(s.squares[k]));
        if (c && std::fabs(c->inside) < kEdgeMargin && c->t <= best.at.t) {
            best.clear = false;
        }
    }
    return best;
}

/// The square a shadow feeler passes on its way from `point` (on square `surface`) to `light`, a
/// point source of square `emitter` (neither of which can block it): kNoSquare if none,
/// kTooCloseToCall if it passes too close to an edge to call. The probe scenes hold at most one
/// such square.
inline int feeler_blocker(const ProbeScene& s, V point, V light, int emitter, int surface) {
    const V span = light - point;
    const double distance = length(span);
    for (int k = 0; k < static_cast<int>(s.squares.size()); ++k) {
        if (k == emitter || k == surface) {
            continue;
        }
        const std::optional<Crossing> c =
            cross_plane(point, span * (1.0 / distance), place(s.squares[k]));
        if (!c || c->t >= distance) {
            continue;
        }
        if (std::fabs(c->inside) < kEdgeMargin) {
            return kTooCloseToCall;
        }
        if (c->inside > 0.0) {
            return k;
        }
    }
    return kNoSquare;
}

/// The probe's tolerance on the .gro's linear intensities: relative 1e-6. The .gro stores float32
/// (relative rounding 6e-8) of a double computation; the renderer's and the probe's arithmetic
/// differ by rounding only (~1e-15). Any formula error the probes target changes a value by far
/// more (a dropped attenuation or cosine: percents).
inline void expect_pixel(const GroPixels& gro, int x, int y, Colour want, const std::string& what) {
    const std::array<double, 3>& got = gro.at(x, y);
    const double wanted[3] = {want.r, want.g, want.b};
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(got[static_cast<std::size_t>(c)], wanted[c], 1e-6 * std::fabs(wanted[c]) + 1e-9)
            << what << ": pixel (" << x << ", " << y << ") channel " << c;
    }
}

}  // namespace rt::test::probe
