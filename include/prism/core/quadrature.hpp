// SPDX-License-Identifier: MIT
// Gauss-Legendre quadrature: n nodes and weights on [-1, 1] that integrate every
// polynomial of degree up to 2n - 1 exactly, and a smooth function nearly so.
//
// The nodes are the roots of the Legendre polynomial P_n, found by Newton's iteration
// from Tricomi's estimate cos(pi (k - 1/4) / (n + 1/2)), P_n and its derivative by the
// three-term recurrence, all in double; the weights are 2 / ((1 - x^2) P_n'(x)^2).
// (Whitted's airlight sums a point light's single scattering with them: integrator/whitted.hpp.)
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/math.hpp>

#include <array>
#include <cmath>

namespace prism {

/// Gauss-Legendre quadrature of `count` nodes (1 to max_count) on [-1, 1].
class GaussLegendre {
public:
    /// The most nodes a rule may have.
    static constexpr int max_count = 64;

    /// The rule of n nodes; throws std::invalid_argument for n outside [1, max_count].
    explicit GaussLegendre(int n) : count_(n)
    {
        if (n < 1 || n > max_count) detail::throw_invalid("GaussLegendre count must be in [1, ", max_count, "], got ", n);
        for (int k = 0; k < (n + 1) / 2; ++k) {
            double x = std::cos(pi<double> * (double(k) + 0.75) / (double(n) + 0.5));
            double derivative = 1;
            for (int iteration = 0; iteration < 100; ++iteration) {
                // P_n(x) and P_n'(x) by (j + 1) P_{j+1} = (2 j + 1) x P_j - j P_{j-1}.
                double p0 = 1, p1 = x;
                for (int j = 1; j < n; ++j) {
                    const double p2 = ((2.0 * j + 1.0) * x * p1 - double(j) * p0) / (double(j) + 1.0);
                    p0 = p1;
                    p1 = p2;
                }
                derivative = double(n) * (x * p1 - p0) / (x * x - 1.0);
                const double step = p1 / derivative;
                x -= step;
                if (std::abs(step) < 1e-16) break;
            }
            nodes_[std::size_t(k)] = -x;
            nodes_[std::size_t(n - 1 - k)] = x;
            weights_[std::size_t(k)] = weights_[std::size_t(n - 1 - k)] = 2.0 / ((1.0 - x * x) * derivative * derivative);
        }
    }

    /// The number of nodes.
    [[nodiscard]] int count() const noexcept { return count_; }
    /// Node k, in [-1, 1], ascending.
    [[nodiscard]] double node(int k) const noexcept { return nodes_[std::size_t(k)]; }
    /// Node k's weight (the weights sum to 2).
    [[nodiscard]] double weight(int k) const noexcept { return weights_[std::size_t(k)]; }

    /// The integral of f over [a, b] by the rule: f(x) at the nodes mapped to [a, b], each
    /// times its weight and (b - a) / 2.
    template <Scalar T, class F>
    [[nodiscard]] auto integrate(T a, T b, F&& f) const noexcept
    {
        const T half = (b - a) / T(2), middle = (a + b) / T(2);
        auto sum = f(middle + half * T(nodes_[0])) * T(weights_[0]);
        for (int k = 1; k < count_; ++k) sum += f(middle + half * T(nodes_[std::size_t(k)])) * T(weights_[std::size_t(k)]);
        return sum * half;
    }

private:
    int count_;
    std::array<double, max_count> nodes_{};
    std::array<double, max_count> weights_{};
};

} // namespace prism
