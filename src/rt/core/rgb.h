// Linear RGB intensities, as the attribute model and the film use them.
#pragma once

namespace rt {

struct Rgb {
    double r = 0.0;
    double g = 0.0;
    double b = 0.0;

    constexpr double operator[](int c) const { return c == 0 ? r : (c == 1 ? g : b); }
    constexpr double& operator[](int c) { return c == 0 ? r : (c == 1 ? g : b); }
    constexpr Rgb& operator+=(const Rgb& o) {
        r += o.r;
        g += o.g;
        b += o.b;
        return *this;
    }
    constexpr Rgb& operator*=(double s) {
        r *= s;
        g *= s;
        b *= s;
        return *this;
    }
    friend constexpr bool operator==(const Rgb&, const Rgb&) = default;
};

constexpr Rgb operator+(Rgb a, const Rgb& b) {
    return a += b;
}
constexpr Rgb operator*(Rgb a, double s) {
    return a *= s;
}
constexpr Rgb operator*(double s, Rgb a) {
    return a *= s;
}
/// Component-wise product: a surface colour filtering light.
constexpr Rgb operator*(const Rgb& a, const Rgb& b) {
    return {a.r * b.r, a.g * b.g, a.b * b.b};
}
constexpr double max_component(const Rgb& c) {
    double m = c.r > c.g ? c.r : c.g;
    return m > c.b ? m : c.b;
}

}  // namespace rt
