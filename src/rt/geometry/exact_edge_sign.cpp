#include "rt/geometry/exact_edge_sign.h"

#include <algorithm>
#include <cmath>

namespace rt {

namespace {

/// A product held exactly as the sum hi + lo.
struct ExactProduct {
    double hi = 0.0;
    double lo = 0.0;
};

ExactProduct two_product(double a, double b) {
    const double hi = a * b;
    return {hi, std::fma(a, b, -hi)};
}

/// s + e == a + b exactly (Knuth's two-sum; no ordering of magnitudes needed).
void two_sum(double a, double b, double& s, double& e) {
    s = a + b;
    const double b_virtual = s - a;
    const double a_virtual = s - b_virtual;
    e = (a - a_virtual) + (b - b_virtual);
}

/// The exact sign of (u.hi + u.lo) - (v.hi + v.lo). The four terms are summed into a
/// non-overlapping expansion (Shewchuk's grow-expansion, smallest component first), whose sign is
/// that of its largest nonzero component.
int difference_sign(const ExactProduct& u, const ExactProduct& v) {
    double e[4] = {u.lo, u.hi, 0.0, 0.0};
    int length = 2;
    for (const double b : {-v.lo, -v.hi}) {
        double q = b;
        for (int i = 0; i < length; ++i) {
            double h = 0.0;
            two_sum(q, e[i], q, h);
            e[i] = h;
        }
        e[length++] = q;
    }
    for (int i = length - 1; i >= 0; --i) {
        if (e[i] != 0.0) {
            return e[i] > 0.0 ? 1 : -1;
        }
    }
    return 0;
}

bool lexicographically_less(const ExactProduct& u, const ExactProduct& v) {
    return u.hi < v.hi || (u.hi == v.hi && u.lo < v.lo);
}

}  // namespace

int exact_edge_sign(double xa, double ya, double xb, double yb) {
    const double largest = std::max({std::fabs(xa), std::fabs(ya), std::fabs(xb), std::fabs(yb)});
    if (!(largest > 0.0) || !std::isfinite(largest)) {
        return 0;  // all zero (the ray through both corners), or not a number at all
    }
    // A power-of-two scale is exact and keeps the products away from overflow and underflow.
    const int shift = -std::ilogb(largest);
    const ExactProduct u = two_product(std::ldexp(xa, shift), std::ldexp(yb, shift));
    const ExactProduct v = two_product(std::ldexp(ya, shift), std::ldexp(xb, shift));
    // Swapping a and b swaps u and v; evaluating in one canonical order makes the result
    // antisymmetric even where extreme underflow would make it inexact.
    if (lexicographically_less(u, v)) {
        return -difference_sign(v, u);
    }
    if (lexicographically_less(v, u)) {
        return difference_sign(u, v);
    }
    return 0;
}

}  // namespace rt
