// SPDX-License-Identifier: MIT
// PhotonMap: photons in a KdTree, and the density estimate of the irradiance they carry.
#pragma once

#include <prism/accel/kd_tree.hpp>
#include <prism/core/parallel.hpp>
#include <prism/photon/estimator.hpp>
#include <prism/photon/photon.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <vector>

namespace prism {

/// The photons' positions, as a PointSet for the KdTree.
struct PhotonPositions {
    /// Photon positions are float.
    using scalar_type = float;
    /// Positions in 3-D.
    static constexpr std::size_t dimension = 3;

    std::span<const Photon> photons; ///< the photons, in the map's order

    /// The number of photons.
    [[nodiscard]] std::size_t size() const noexcept { return photons.size(); }
    /// Coordinate `axis` of photon i's position.
    [[nodiscard]] float coordinate(std::size_t i, std::size_t axis) const noexcept { return photons[i].position[static_cast<int>(axis)]; }
};

/// A density estimate and the squared radius of the disk it was gathered over.
struct PrecomputedIrradiance {
    Rgb<float> irradiance{0.0f}; ///< the estimate of the irradiance
    float radius2 = 0; ///< the squared radius it was gathered over
};

/// Photons in KD-tree order, with radius and k-nearest radiance estimates (Jensen 2001).
class PhotonMap {
public:
    /// The KD-tree over the photons' positions (8 a leaf).
    using Tree = KdTree<PhotonPositions, 8>;
    static constexpr std::size_t max_k = 512; ///< the most photons a k-nearest estimate gathers

    PhotonMap() = default;

    /// Own the photons and build the tree over them (on up to `threads` threads, 0 = all
    /// hardware threads; the same tree for any count). The photons are then put in tree
    /// order, so that every subtree's photons (and each leaf's) lie together in memory
    /// and an estimate reads them with few cache misses.
    explicit PhotonMap(std::vector<Photon> photons, unsigned threads = 1) : tree_(std::in_place, PhotonPositions{photons}, threads)
    {
        photons_.resize(photons.size());
        const auto order = tree_->order();
        detail::parallel_for(order.size(), threads, [&](std::size_t i) { photons_[i] = photons[order[i]]; });
        tree_->index_in_tree_order();
    }

    /// The number of photons.
    [[nodiscard]] std::size_t size() const noexcept { return photons_.size(); }
    /// The photons, in tree order.
    [[nodiscard]] const std::vector<Photon>& photons() const noexcept { return photons_; }

    /// Irradiance at p on a surface with unit normal n (Jensen 1996, eq. 6 with a diffuse
    /// BRDF taken out): the filtered sum of the powers of the photons on surfaces facing
    /// n's way, over the disk pi r^2 that holds them. With k nearest, r reaches the k-th
    /// and that photon, on the disk's rim, is left out: (k - 1) / (pi r^2) is unbiased
    /// for a uniform random density, k / (pi r^2) reads k / (k - 1) high (1.6 % at 64).
    /// When fewer were found r is the search's maximum and every photon within it counts.
    /// Shadow photons carry no power. Calibrated: each photon carries power / photons
    /// emitted, so the estimate does not depend on the count.
    [[nodiscard]] Rgb<float> irradiance(const Vec3<float>& p, const Vec3<float>& n, const Estimator& estimator) const noexcept
    {
        return estimate(p, n, estimator).irradiance;
    }

    /// irradiance(), with the squared radius of the disk it was gathered over (0 where
    /// no photon was found).
    [[nodiscard]] PrecomputedIrradiance estimate(const Vec3<float>& p, const Vec3<float>& n, const Estimator& estimator) const noexcept
    {
        return estimate(p, n, estimator, [](const Photon& photon) { return photon.power(); });
    }

    /// Reflected radiance at p on a surface with unit normal n (Jensen 1996, eq. 6): as
    /// irradiance(), each photon's power weighed by the BSDF between its direction and
    /// the viewer's, `reflected(photon)` (its power times f): a glossy surface's estimate.
    template <class Reflected>
    [[nodiscard]] Rgb<float> radiance(const Vec3<float>& p, const Vec3<float>& n, const Estimator& estimator, Reflected&& reflected) const noexcept
    {
        return estimate(p, n, estimator, reflected).irradiance;
    }

    /// The density estimate of `value(photon)` over the disk (estimate() with the photons' powers).
    template <class Value>
    [[nodiscard]] PrecomputedIrradiance estimate(const Vec3<float>& p, const Vec3<float>& n, const Estimator& estimator, Value&& value) const noexcept
    {
        Rgb<float> sum(0.0f);
        if (!tree_ || photons_.empty() || !(estimator.radius > 0.0f)) return {sum, 0.0f};
        const detail::FilterWeight weight(estimator.filter);
        const auto add = [&](std::uint32_t index, float d2, float r2) {
            const Photon& photon = photons_[index];
            if ((photon.flags & estimator.excluded) != 0 || photon.segments() > estimator.max_segments || !photon.faces(n, estimator.surface_cos)) return;
            const float height = dot(photon.position - p, n);
            if (height * height > estimator.max_height_ratio * estimator.max_height_ratio * r2) return;
            sum += value(photon) * weight(d2, r2);
        };
        float r2 = estimator.radius * estimator.radius;
        if (estimator.k == 0) {
            // A radius whose square underflows (below 1e-19) holds no density float can
            // state: nothing, as for k nearest all at one point (it divided 0 by 0).
            if (!(r2 > 0.0f)) return {sum, 0.0f};
            tree_->within({p.x, p.y, p.z}, estimator.radius, [&](std::uint32_t index, float d2) { add(index, d2, r2); });
        } else {
            std::array<Neighbour<float>, max_k> buffer;
            KNearest<float> found(buffer, estimator.k, r2);
            tree_->search({p.x, p.y, p.z}, found);
            if (found.size() == 0) return {sum, 0.0f};
            const bool rim = found.full();
            if (rim || !(r2 < infinity<float>)) r2 = found.farthest().distance2;
            if (!(r2 > 0.0f)) return {Rgb<float>(0.0f), 0.0f};
            const std::uint32_t on_rim = rim ? found.farthest().index : std::numeric_limits<std::uint32_t>::max();
            for (const Neighbour<float>& neighbour : found)
                if (neighbour.index != on_rim) add(neighbour.index, neighbour.distance2, r2);
        }
        return {sum / (weight.mean() * pi<float> * r2), r2};
    }

    /// visit(photon, t, distance2) for every photon within `radius` of the segment from
    /// `origin` along unit `direction` whose projection t lies in [t_min, t_max],
    /// distance2 its squared distance from the line: the photons a beam
    /// radiance estimate of that radius gathers (Jarosz et al. 2008, "The Beam Radiance
    /// Estimate for Volumetric Photon Mapping"; with a box kernel the estimate is their
    /// weighted sum over pi r^2).
    template <class Visit>
    void near_beam(const Vec3<float>& origin, const Vec3<float>& direction, float t_min, float t_max, float radius, Visit&& visit) const
    {
        if (!tree_ || photons_.empty() || !(radius > 0.0f)) return;
        tree_->along({origin.x, origin.y, origin.z}, {direction.x, direction.y, direction.z}, t_min, t_max, radius,
                     [&](std::uint32_t index, float t, float distance2) { visit(photons_[index], t, distance2); });
    }

    /// The volume radiance estimate's sum (Jensen and Christensen 1998): the sum of
    /// value(photon) over the photons within `radius` of p, over the sphere's volume.
    template <class Value>
    [[nodiscard]] Rgb<float> in_sphere(const Vec3<float>& p, float radius, Value&& value) const noexcept
    {
        Rgb<float> sum(0.0f);
        if (!tree_ || photons_.empty() || !(radius > 0.0f)) return sum;
        tree_->within({p.x, p.y, p.z}, radius, [&](std::uint32_t index, float) { sum += value(photons_[index]); });
        return sum / (4.0f / 3.0f * pi<float> * radius * radius * radius);
    }

    /// The box-filtered estimate from the K nearest, searched without limit.
    template <std::size_t K>
    [[nodiscard]] Rgb<float> irradiance(const Vec3<float>& p, const Vec3<float>& n) const noexcept
    {
        static_assert(K <= max_k);
        return irradiance(p, n, {.k = K, .radius = infinity<float>});
    }

    /// The box-filtered estimate within a fixed radius, leaving out photons with any of
    /// the `excluded` flags.
    [[nodiscard]] Rgb<float> irradiance_within(const Vec3<float>& p, const Vec3<float>& n, float radius,
                                               std::uint8_t excluded = 0) const noexcept
    {
        return irradiance(p, n, {.radius = radius, .excluded = excluded});
    }

    /// Precompute irradiance at every `stride`-th photon from its K nearest (Christensen
    /// 1999, "Faster Photon Map Global Illumination"), so that a final-gather ray needs
    /// one nearest-neighbour lookup instead of a density estimate.
    /// The estimates run on up to `threads` threads (0 = all hardware threads), each
    /// written to its sample's place: the same values for any count.
    template <std::size_t K>
    void precompute_irradiance(std::size_t stride, unsigned threads = 1)
    {
        std::vector<Photon> samples = irradiance_samples(stride);
        std::vector<PrecomputedIrradiance> values(samples.size());
        detail::parallel_for(samples.size(), threads, [&](std::size_t i) { values[i] = precomputed_estimate<K>(samples[i]); });
        set_precomputed_irradiance(std::move(samples), std::move(values), threads);
    }

    /// The estimate precompute_irradiance<K> keeps at a sample.
    template <std::size_t K>
    [[nodiscard]] PrecomputedIrradiance precomputed_estimate(const Photon& sample) const noexcept
    {
        static_assert(K <= max_k);
        return estimate(sample.position, sample.normal(), {.k = K, .radius = infinity<float>});
    }

    /// The photons precompute_irradiance estimates at: every `stride`-th, but for shadow
    /// photons.
    [[nodiscard]] std::vector<Photon> irradiance_samples(std::size_t stride) const
    {
        std::vector<Photon> samples;
        for (std::size_t i = 0; i < photons_.size(); i += std::max<std::size_t>(stride, 1))
            if (!(photons_[i].flags & Photon::shadow)) samples.push_back(photons_[i]);
        return samples;
    }

    /// Irradiance precomputed elsewhere (by processes that each estimated a share of the
    /// samples): estimates[i] = precomputed_estimate<K>(samples[i]), samples from
    /// irradiance_samples.
    void set_precomputed_irradiance(std::vector<Photon> samples, std::vector<PrecomputedIrradiance> estimates, unsigned threads = 1)
    {
        if (samples.size() != estimates.size())
            detail::throw_invalid("PhotonMap set_precomputed_irradiance: ", samples.size(), " samples and ", estimates.size(), " estimates");
        irradiance_ = std::move(estimates);
        samples_ = std::move(samples);
        sample_tree_.emplace(PhotonPositions{samples_}, threads);
    }

    /// Whether precompute_irradiance() has been run (the final gather needs it).
    [[nodiscard]] bool has_precomputed_irradiance() const noexcept { return sample_tree_.has_value(); }

    /// The precomputed irradiance nearest p among samples on surfaces facing n's way
    /// whose estimate's disk reaches p (zero when there are none). Without that reach, a
    /// point no photon can reach (inside a closed diffuse ball, the floor beneath it) read
    /// the nearest sample outside, however far: light through walls.
    [[nodiscard]] Rgb<float> precomputed_irradiance(const Vec3<float>& p, const Vec3<float>& n) const noexcept
    {
        if (!sample_tree_ || samples_.empty()) return Rgb<float>(0.0f);
        for (const Neighbour<float>& neighbour : sample_tree_->nearest<4>({p.x, p.y, p.z})) {
            const PrecomputedIrradiance& e = irradiance_[neighbour.index];
            if (neighbour.distance2 <= e.radius2 && samples_[neighbour.index].faces(n, Estimator{}.surface_cos)) return e.irradiance;
        }
        return Rgb<float>(0.0f);
    }

    /// How many of the k nearest photons within max_radius on surfaces facing n's way are
    /// direct, and how many are shadow photons (Jensen and Christensen 1995: all direct
    /// means lit, all shadow means in shadow).
    [[nodiscard]] std::pair<std::size_t, std::size_t> direct_and_shadow(const Vec3<float>& p, const Vec3<float>& n, std::size_t k,
                                                                        float max_radius) const noexcept
    {
        std::size_t direct = 0, shadow = 0;
        if (!tree_ || !(max_radius >= 0.0f)) return {0, 0};
        std::array<Neighbour<float>, max_k> buffer;
        KNearest<float> found(buffer, k, max_radius * max_radius);
        tree_->search({p.x, p.y, p.z}, found);
        for (const Neighbour<float>& neighbour : found) {
            const Photon& photon = photons_[neighbour.index];
            if (!photon.faces(n, Estimator{}.surface_cos)) continue;
            direct += (photon.flags & Photon::direct) != 0;
            shadow += (photon.flags & Photon::shadow) != 0;
        }
        return {direct, shadow};
    }

private:
    std::vector<Photon> photons_;
    std::optional<Tree> tree_;
    std::vector<Photon> samples_;         ///< photons at which irradiance was precomputed
    std::vector<PrecomputedIrradiance> irradiance_; ///< their irradiance, and the squared radius it was estimated over
    std::optional<Tree> sample_tree_;
};

} // namespace prism
