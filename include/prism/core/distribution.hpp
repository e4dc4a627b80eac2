// SPDX-License-Identifier: MIT
// AliasTable: one of n items by weight, in constant time (Walker 1977, built as Vose 1991).
//
// Each of n equal bins holds a share q of its own item and 1 - q of one other (its
// alias). One uniform number picks the bin by its integer part and the item by its
// fraction, and what is left of the fraction is handed back, rescaled to [0, 1), so a
// caller can place the sample within the item (a point on the emitter picked) with the
// same number, stratified as the number was. The table is built in double, so items whose
// weights differ by many orders of magnitude keep their probabilities.
//
// AliasTable2D: a cell of a grid (an image's pixel) by weight, as a row by the rows' sums
// and then a column by that row's weights, in constant time; each number's rest places the
// sample within the cell.
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

/// A cell drawn from an AliasTable2D: its column and row, its probability, and what is left
/// of the two uniform numbers (the row's and the column's), each uniform in [0, 1) again.
template <Scalar T>
struct AliasPick2D {
    std::uint32_t x = 0;   ///< the column drawn
    std::uint32_t y = 0;   ///< the row drawn
    T probability = T(0);  ///< the cell's weight over the sum of all weights
    Vec2<T> rest{};        ///< what is left of u.x (by the row) and of u.y (by the column)
};

/// Picks cell (x, y) of a width x height grid with probability weight(x, y) / sum of the
/// weights, in O(1): the row by u.x among the rows' sums, then the column by u.y among the
/// row's own weights.
template <Scalar T>
class AliasTable2D {
public:
    /// An empty table (it picks nothing).
    AliasTable2D() = default;

    /// The table for `weights`, row by row (width x height of them); throws
    /// std::invalid_argument, naming `what` and the cell, for a negative or non-finite
    /// weight, no positive weight, a size that is not width x height, or a side of 2^32 or more.
    AliasTable2D(std::size_t width, std::size_t height, std::span<const double> weights, std::string_view what = "AliasTable2D weight")
    {
        if (width == 0 || height == 0 || width >= 0xffffffffu || height >= 0xffffffffu || weights.size() / width != height ||
            weights.size() % width != 0)
            detail::throw_invalid(what, ": ", weights.size(), " weights for a grid of ", width, " x ", height);
        std::vector<double> sums(height, 0.0);
        width_ = width;
        columns_.resize(height);
        for (std::size_t y = 0; y < height; ++y) {
            const std::span<const double> row = weights.subspan(y * width, width);
            for (std::size_t x = 0; x < width; ++x) {
                if (!(row[x] >= 0) || !is_finite(row[x])) detail::throw_invalid(what, " (", x, ", ", y, ") must be finite and >= 0, got ", row[x]);
                sums[y] += row[x];
            }
            // A row that weighs nothing is never picked, and needs no table.
            if (sums[y] > 0) columns_[y] = AliasTable<T>(row, what);
        }
        rows_ = AliasTable<T>(sums, what);
    }

    /// The grid's width.
    [[nodiscard]] std::size_t width() const noexcept { return width_; }
    /// The grid's height.
    [[nodiscard]] std::size_t height() const noexcept { return columns_.size(); }
    /// Whether the table has no cell.
    [[nodiscard]] bool empty() const noexcept { return columns_.empty(); }

    /// The probability of cell (x, y).
    [[nodiscard]] T probability(std::size_t x, std::size_t y) const noexcept
    {
        return columns_[y].empty() ? T(0) : rows_.probability(y) * columns_[y].probability(x);
    }

    /// The cell for the uniform numbers u in [0, 1)^2; not on an empty table.
    [[nodiscard]] AliasPick2D<T> pick(const Vec2<T>& u) const noexcept
    {
        const AliasPick<T> row = rows_.pick(u.x);
        const AliasPick<T> column = columns_[row.index].pick(u.y);
        return {column.index, row.index, row.probability * column.probability, {row.rest, column.rest}};
    }

private:
    std::size_t width_ = 0;              ///< cells a row
    AliasTable<T> rows_;                 ///< by the rows' sums
    std::vector<AliasTable<T>> columns_; ///< each row by its own weights (empty for a row that weighs nothing)
};

} // namespace prism
