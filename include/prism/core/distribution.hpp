// SPDX-License-Identifier: MIT
// AliasTable: one of n items by weight, in constant time (Walker 1977, built as Vose 1991).
//
// Each of n equal bins holds a share q of its own item and 1 - q of one other (its
// alias). One uniform number picks the bin by its integer part and the item by its
// fraction, and what is left of the fraction is handed back, rescaled to [0, 1), so a
// caller can place the sample within the item (a point on the emitter picked) with the
// same number, stratified as the number was. The table is built in double, so items whose
// weights differ by many orders of magnitude keep their probabilities.
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/math.hpp>

#include <algorithm>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace prism {

/// An item drawn from an AliasTable: its index, its probability, and the uniform number
/// left over, in [0, 1).
template <Scalar T>
struct AliasPick {
    std::uint32_t index = 0; ///< the item drawn
    T probability = T(0);    ///< its weight over the sum of the weights
    T rest = T(0);           ///< what is left of the uniform number, uniform in [0, 1) again
};

/// Picks item i of n with probability weight_i / sum of weights, in O(1) per pick.
template <Scalar T>
class AliasTable {
public:
    /// An empty table (it picks nothing).
    AliasTable() = default;

    /// The table for `weights`; throws std::invalid_argument, naming `what` and the item,
    /// for a negative or non-finite weight, no positive weight, or 2^32 items or more.
    AliasTable(std::span<const double> weights, std::string_view what = "AliasTable weight")
    {
        if (weights.size() >= 0xffffffffu) detail::throw_invalid(what, ": ", weights.size(), " items, at most 2^32 - 2");
        double sum = 0;
        for (std::size_t i = 0; i < weights.size(); ++i) {
            if (!(weights[i] >= 0) || !is_finite(weights[i])) detail::throw_invalid(what, " ", i, " must be finite and >= 0, got ", weights[i]);
            sum += weights[i];
        }
        if (!(sum > 0) || !is_finite(sum)) detail::throw_invalid(what, ": the weights must have a positive, finite sum, got ", sum, " over ", weights.size());
        const std::size_t n = weights.size();
        bins_.resize(n);
        std::vector<double> scaled(n);
        std::vector<std::uint32_t> small, large;
        for (std::size_t i = 0; i < n; ++i) {
            bins_[i].probability = T(weights[i] / sum);
            scaled[i] = weights[i] / sum * double(n);
            (scaled[i] < 1 ? small : large).push_back(std::uint32_t(i));
        }
        // Vose: fill each under-full bin from an over-full item, which becomes under-full
        // in turn when it has given more than its excess.
        while (!small.empty() && !large.empty()) {
            const std::uint32_t s = small.back(), l = large.back();
            small.pop_back();
            bins_[s].share = T(scaled[s]);
            bins_[s].alias = l;
            scaled[l] -= 1 - scaled[s];
            if (scaled[l] < 1) {
                large.pop_back();
                small.push_back(l);
            }
        }
        // What is left is full to rounding: keep all of it.
        for (const std::uint32_t i : large) bins_[i].share = T(1), bins_[i].alias = i;
        for (const std::uint32_t i : small) bins_[i].share = T(1), bins_[i].alias = i;
    }

    /// The number of items.
    [[nodiscard]] std::size_t size() const noexcept { return bins_.size(); }
    /// Whether the table has no item.
    [[nodiscard]] bool empty() const noexcept { return bins_.empty(); }
    /// The probability of item i.
    [[nodiscard]] T probability(std::size_t i) const noexcept { return bins_[i].probability; }

    /// The item for the uniform number u in [0, 1); not on an empty table.
    [[nodiscard]] AliasPick<T> pick(T u) const noexcept
    {
        PRISM_ASSERT(!bins_.empty());
        const T scaled = u * T(bins_.size());
        const std::uint32_t bin = std::min(std::uint32_t(scaled), std::uint32_t(bins_.size() - 1));
        const T fraction = std::min(scaled - T(bin), one_below);
        const Bin& b = bins_[bin];
        if (fraction < b.share) return {bin, b.probability, std::min(fraction / b.share, one_below)};
        return {b.alias, bins_[b.alias].probability, std::min((fraction - b.share) / (T(1) - b.share), one_below)};
    }

private:
    struct Bin {
        T share = T(1);          ///< the bin's share that is its own item
        std::uint32_t alias = 0; ///< the item holding the rest
        T probability = T(0);    ///< this item's probability
    };
    static constexpr T one_below = T(1) - std::numeric_limits<T>::epsilon() / T(2);

    std::vector<Bin> bins_;
};

} // namespace prism
