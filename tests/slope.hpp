// SPDX-License-Identifier: MIT
// The least-squares slope of log y against log x: how fast an error falls with the
// samples (-1/2 for independent samples, -1 to -3/2 for low-discrepancy points).
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

namespace test {

inline double log_log_slope(const std::vector<double>& x, const std::vector<double>& y)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    const double n = double(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
        const double lx = std::log(x[i]), ly = std::log(y[i]);
        sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
    }
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

} // namespace test
