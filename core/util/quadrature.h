#pragma once
// Gauss–Legendre quadrature on [−1, 1]: n nodes integrate polynomials of degree < 2n exactly.
// Used for exact per-pixel solid angles of light probes and by tests that need exact sphere sums.

#include <vector>

namespace thespis::core {

struct GaussLegendreRule {
    std::vector<double> x; ///< nodes, descending
    std::vector<double> w; ///< weights, summing to 2
};

/// The n-point rule (n ≥ 1), by Newton's method on the Legendre recurrence, to full double precision.
GaussLegendreRule gaussLegendre(int n);

} // namespace thespis::core
