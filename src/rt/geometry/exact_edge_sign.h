// The slow, exact half of edge_sign(): used only when the quick floating-point evaluation is too
// close to zero to trust.
#pragma once

namespace rt {

/// The exact sign of xa * yb - ya * xb for finite inputs, by error-free products and expansion
/// arithmetic (Shewchuk 1997). Exact unless the inputs' magnitudes differ by more than about 2^900
/// (products underflowing); antisymmetric under swapping a and b in every case.
int exact_edge_sign(double xa, double ya, double xb, double yb);

}  // namespace rt
