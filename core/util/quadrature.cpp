#include "util/quadrature.h"

#include <cassert>
#include <cmath>
#include <numbers>

namespace thespis::core {

GaussLegendreRule gaussLegendre(int n)
{
    assert(n >= 1);
    GaussLegendreRule rule{std::vector<double>(size_t(n)), std::vector<double>(size_t(n))};
    for (int i = 0; i < n; ++i) {
        double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5)); // Tricomi's first guess
        double derivative = 1.0;
        for (int iteration = 0; iteration < 100; ++iteration) {
            double p0 = 1.0, p1 = x;
            for (int k = 2; k <= n; ++k) {
                const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            derivative = n * (x * p1 - p0) / (x * x - 1.0);
            const double step = p1 / derivative;
            x -= step;
            if (std::abs(step) < 1e-16)
                break;
        }
        rule.x[size_t(i)] = x;
        rule.w[size_t(i)] = 2.0 / ((1.0 - x * x) * derivative * derivative);
    }
    return rule;
}

} // namespace thespis::core
