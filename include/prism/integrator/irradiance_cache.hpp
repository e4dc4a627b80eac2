// SPDX-License-Identifier: MIT
// The final gather's hemisphere, stratified, with irradiance gradients (Ward and
// Heckbert 1992), and an irradiance cache that interpolates between gathers.
//
// gather_hemisphere: M x N cells of equal projected solid angle (sin^2 theta uniform in
// j, phi in k), one jittered ray each: E = pi / (M N) sum L_jk. From the same rays,
// the rotational gradient (how E turns with the normal) and the translational one (how
// it moves along the surface), in the notation of Krivanek and Gautron's "Practical
// Global Illumination with Irradiance Caching" (2009), section 2.2:
//   rotational     pi / (M N) sum_k v_k sum_j (-tan theta_j) L_jk   (tan theta_j and v_k
//                  the cell's means, v a quarter turn back from u)
//   translational  sum_k u_k (2 pi / N) sum_{j>=1} cos^2 theta_j- sin theta_j- (L_jk - L_j-1,k) / min(R_jk, R_j-1,k)
//                + sum_k v_k- sum_j cos theta_j (cos theta_j- - cos theta_j+) (L_jk - L_j,k-1) / (sin theta_j min(R_jk, R_j,k-1))
// with theta_j- and theta_j+ the cell's edges, u_k and v_k the base-plane directions at
// the cell's azimuth and a quarter turn from it, v_k- at the edge between k - 1 and k.
//
// IrradianceCache: records of (p, n, E, gradients, R) where R, the distance over which E
// may change, is the nearest hit of the gather (rays within 10 degrees of the tangent
// plane left out), limited by E / |grad E|, clamped between a few pixels' footprint
// and a fraction of the scene, and by each neighbour's R plus its distance (Krivanek's
// neighbour clamping). A record is used at p with normal n where
//     eps = kappa max(|p - p_i| / R_i, sqrt(1 - n . n_i) / sqrt(1 - cos 10 deg)) < 1,
// weighted by 1 - eps (Tabellion and Lamourlette 2004: weights that fall to 0 at the
// edge of a record's reach, so no seams), and not where the record lies in front of p.
#pragma once

#include <prism/accel/kd_tree.hpp>
#include <prism/core/math.hpp>
#include <prism/core/random.hpp>
#include <prism/core/sampling.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <optional>
#include <span>
#include <vector>

namespace prism {

/// What a gather over the hemisphere found.
template <Scalar T>
struct HemisphereGather {
    Rgb<T> irradiance{T(0)}; ///< the irradiance E, per channel
    std::array<Rgb<T>, 3> rotational{};    ///< d E / d (rotation about axis a): per axis a, per channel
    std::array<Rgb<T>, 3> translational{}; ///< d E / d x_a: per axis a, per channel
    T nearest = infinity<T>;               ///< the nearest hit of rays at least 10 degrees above the tangent plane
};

/// A gather over the hemisphere about unit n in M x N stratified cells:
/// sample(direction) returns {radiance arriving, distance to where it came from
/// (infinity when nothing)}. With Gradients, each cell's radiance and distance are
/// kept for them (the one allocation, per gather: a cache record's); without, nothing
/// is allocated.
template <bool Gradients, Scalar T, class Sample>
[[nodiscard]] HemisphereGather<T> gather_hemisphere(const Vec3<T>& n, int m, int cells_n, Random& rng, Sample&& sample)
{
    const auto [t, b] = orthonormal_frame(n);
    const std::size_t count = std::size_t(m) * std::size_t(cells_n);
    std::vector<Rgb<T>> radiance;
    std::vector<T> distance;
    if constexpr (Gradients) {
        radiance.resize(count);
        distance.resize(count);
    }
    const auto in_plane = [&](T phi) { return t * std::cos(phi) + b * std::sin(phi); };
    HemisphereGather<T> g;
    for (int j = 0; j < m; ++j)
        for (int k = 0; k < cells_n; ++k) {
            const T sin2 = (T(j) + rng.uniform<T>()) / T(m), phi = T(2) * pi<T> * (T(k) + rng.uniform<T>()) / T(cells_n);
            const T cos_theta = std::sqrt(std::max(T(0), T(1) - sin2));
            const auto [l, d] = sample(normalize(in_plane(phi) * std::sqrt(sin2) + n * cos_theta));
            if constexpr (Gradients) {
                radiance[std::size_t(j * cells_n + k)] = l;
                distance[std::size_t(j * cells_n + k)] = d;
            }
            g.irradiance += l;
            if (cos_theta > T(0.173648)) g.nearest = std::min(g.nearest, d); // 10 degrees
        }
    const T cell = pi<T> / T(count);
    g.irradiance *= cell;
    if constexpr (!Gradients) return g;
    // The rotational term weighs each cell by its mean of tan theta and of v over the
    // cell (not their values at its centre, which read 8 % low at M = 32): with s =
    // sin^2 theta uniform in [j/M, (j+1)/M], the mean of tan theta is M (F(b) - F(a)),
    // F(s) = asin(sqrt s) - sqrt(s (1 - s)); v's mean over the cell's azimuths is v at
    // its centre times sin(pi / N) / (pi / N).
    const auto f = [](T x) { return std::asin(std::sqrt(x)) - std::sqrt(x * (T(1) - x)); };
    const T sinc = std::sin(pi<T> / T(cells_n)) / (pi<T> / T(cells_n));
    for (int j = 0; j < m; ++j) {
        const T sin_minus = std::sqrt(T(j) / T(m)), cos_minus = std::sqrt(T(1) - T(j) / T(m));
        const T cos_plus = std::sqrt(std::max(T(0), T(1) - T(j + 1) / T(m)));
        const T sin_mid = std::sqrt((T(j) + T(0.5)) / T(m)), cos_mid = std::sqrt(T(1) - (T(j) + T(0.5)) / T(m));
        for (int k = 0; k < cells_n; ++k) {
            const T phi = T(2) * pi<T> * (T(k) + T(0.5)) / T(cells_n);
            const Vec3<T> u_k = in_plane(phi), v_k = in_plane(phi - pi<T> / T(2));
            const Vec3<T> v_edge = in_plane(T(2) * pi<T> * T(k) / T(cells_n) + pi<T> / T(2));
            const std::size_t at = std::size_t(j * cells_n + k);
            const T mean_tan = T(m) * (f(T(j + 1) / T(m)) - f(T(j) / T(m)));
            const Rgb<T> rot = radiance[at] * (-mean_tan * sinc * cell);
            for (int a = 0; a < 3; ++a) g.rotational[std::size_t(a)] += rot * v_k[a];
            if (j > 0) {
                const std::size_t below = std::size_t((j - 1) * cells_n + k);
                const T r = std::min(distance[at], distance[below]);
                if (r < infinity<T>) {
                    const Rgb<T> dl = (radiance[at] - radiance[below]) * (T(2) * pi<T> / T(cells_n) * cos_minus * cos_minus * sin_minus / r);
                    for (int a = 0; a < 3; ++a) g.translational[std::size_t(a)] += dl * u_k[a];
                }
            }
            const std::size_t before = std::size_t(j * cells_n + (k + cells_n - 1) % cells_n);
            const T r = std::min(distance[at], distance[before]);
            if (r < infinity<T>) {
                const Rgb<T> dl = (radiance[at] - radiance[before]) * (cos_mid * (cos_minus - cos_plus) / (sin_mid * r));
                for (int a = 0; a < 3; ++a) g.translational[std::size_t(a)] += dl * v_edge[a];
            }
        }
    }
    return g;
}

/// One cached gather.
template <Scalar T>
struct IrradianceRecord {
    Vec3<T> p{}; ///< where the gather was taken
    Vec3<T> n{}; ///< the surface's normal there
    HemisphereGather<T> gather{}; ///< the gather: E and its gradients
    T radius = T(0); ///< R: how far E may be carried
};

/// The positions of a cache's records, as a PointSet for the KdTree.
template <Scalar T>
struct RecordPositions {
    /// The coordinates' type.
    using scalar_type = T;
    /// Positions in 3-D.
    static constexpr std::size_t dimension = 3;
    std::span<const IrradianceRecord<T>> records; ///< the cache's records
    /// The number of records.
    [[nodiscard]] std::size_t size() const noexcept { return records.size(); }
    /// Coordinate `axis` of record i's position.
    [[nodiscard]] T coordinate(std::size_t i, std::size_t axis) const noexcept { return records[i].p[int(axis)]; }
};

/// Ward's irradiance cache (Ward and Heckbert 1992, "Irradiance gradients"): gathered
/// irradiance records with gradients, interpolated between them.
template <Scalar T>
class IrradianceCache {
public:
    /// sqrt(1 - cos 10 degrees): a normal turned by 10 degrees counts as far as a point R away.
    static constexpr T normal_scale = T(0.1321); // sqrt(1 - 0.98481)

    IrradianceCache() = default;
    /// An empty cache whose records reach R / accuracy (kappa), with or without gradients.
    explicit IrradianceCache(T accuracy, bool gradients = true) : accuracy_(accuracy), gradients_(gradients) {}

    /// The number of records.
    [[nodiscard]] std::size_t size() const noexcept { return records_.size(); }
    /// The records, in the order they were added.
    [[nodiscard]] const std::vector<IrradianceRecord<T>>& records() const noexcept { return records_; }

    /// Add records (in the order given: the cache is then the same for any thread count
    /// that computed them), clamping each one's radius by its neighbours' and theirs by
    /// its own, then index them.
    void add(std::vector<IrradianceRecord<T>> fresh)
    {
        for (IrradianceRecord<T>& record : fresh) {
            for (IrradianceRecord<T>& other : nearby(record.p, record.radius)) {
                const T d = length(record.p - other.p);
                record.radius = std::min(record.radius, other.radius + d);
                other.radius = std::min(other.radius, record.radius + d);
            }
            records_.push_back(record);
            largest_ = std::max(largest_, record.radius);
            pending_.push_back(records_.size() - 1);
            if (pending_.size() > 64) reindex();
        }
        reindex();
    }

    /// The interpolated irradiance at p with unit normal n, or nothing where no record reaches.
    [[nodiscard]] std::optional<Rgb<T>> irradiance(const Vec3<T>& p, const Vec3<T>& n) const noexcept
    {
        Rgb<T> sum{T(0)};
        T weights = T(0);
        visit_within(p, largest_ / accuracy_, [&](const IrradianceRecord<T>& r) {
            const T w = weight(r, p, n);
            if (!(w > T(0))) return;
            Rgb<T> e = r.gather.irradiance;
            if (gradients_) {
                const Vec3<T> turn = cross(r.n, n), moved = p - r.p;
                for (int a = 0; a < 3; ++a) e += r.gather.rotational[std::size_t(a)] * turn[a] + r.gather.translational[std::size_t(a)] * moved[a];
                e = max(e, Rgb<T>(T(0)));
            }
            sum += e * w;
            weights += w;
        });
        if (!(weights > T(0))) return std::nullopt;
        return sum / weights;
    }

    /// Whether some record reaches p with normal n.
    [[nodiscard]] bool covers(const Vec3<T>& p, const Vec3<T>& n) const noexcept
    {
        bool found = false;
        visit_within(p, largest_ / accuracy_, [&](const IrradianceRecord<T>& r) { found = found || weight(r, p, n) > T(0); });
        return found;
    }

private:
    /// Tabellion and Lamourlette's weight, 0 outside the record's reach or where the
    /// record lies in front of p (Ward: its hemisphere sees something p's does not).
    [[nodiscard]] T weight(const IrradianceRecord<T>& r, const Vec3<T>& p, const Vec3<T>& n) const noexcept
    {
        const Vec3<T> moved = p - r.p;
        const T turned = std::sqrt(std::max(T(0), T(1) - dot(n, r.n)));
        const T eps = accuracy_ * std::max(length(moved) / r.radius, turned / normal_scale);
        if (!(eps < T(1))) return T(0);
        if (dot(moved, (n + r.n) * T(0.5)) < -T(0.05) * r.radius) return T(0);
        return T(1) - eps;
    }

    /// visit(record) for each record within `reach` of p: through the tree for the
    /// indexed ones, one by one for the few added since.
    template <class Visit>
    void visit_within(const Vec3<T>& p, T reach, Visit&& visit) const
    {
        if (tree_) tree_->within({p.x, p.y, p.z}, reach, [&](std::uint32_t i, T) { visit(records_[i]); });
        for (const std::size_t i : pending_)
            if (length_squared(records_[i].p - p) <= reach * reach) visit(records_[i]);
    }

    /// The records within radius + largest of p (those whose clamping may involve p's).
    std::vector<std::reference_wrapper<IrradianceRecord<T>>> nearby(const Vec3<T>& p, T radius)
    {
        std::vector<std::reference_wrapper<IrradianceRecord<T>>> out;
        const T reach = radius + largest_;
        if (tree_) tree_->within({p.x, p.y, p.z}, reach, [&](std::uint32_t i, T) { out.push_back(records_[i]); });
        for (const std::size_t i : pending_)
            if (length_squared(records_[i].p - p) <= reach * reach) out.push_back(records_[i]);
        return out;
    }

    void reindex()
    {
        tree_.emplace(RecordPositions<T>{records_});
        pending_.clear();
    }

    T accuracy_ = T(1);
    bool gradients_ = true;
    std::vector<IrradianceRecord<T>> records_;
    std::optional<KdTree<RecordPositions<T>, 8>> tree_;
    std::vector<std::size_t> pending_;   ///< records added since the tree was built
    T largest_ = T(0);                   ///< the largest radius
};

} // namespace prism
