// SPDX-License-Identifier: MIT
// PhotonMap: photons in a KdTree, and the density estimate of the irradiance they carry.
#pragma once

#include <prism/accel/kd_tree.hpp>
#include <prism/photon/photon.hpp>

#include <algorithm>
#include <optional>
#include <span>
#include <vector>

namespace prism {

/// The photons' positions, as a PointSet for the KdTree.
struct PhotonPositions {
    using scalar_type = float;
    static constexpr std::size_t dimension = 3;

    std::span<const Photon> photons;

    [[nodiscard]] std::size_t size() const noexcept { return photons.size(); }
    [[nodiscard]] float coordinate(std::size_t i, std::size_t axis) const noexcept { return photons[i].position[static_cast<int>(axis)]; }
};

class PhotonMap {
public:
    using Tree = KdTree<PhotonPositions, 8>;

    PhotonMap() = default;

    /// Own the photons and build the tree over them.
    explicit PhotonMap(std::vector<Photon> photons) : photons_(std::move(photons)), tree_(std::in_place, PhotonPositions{photons_}) {}

    [[nodiscard]] std::size_t size() const noexcept { return photons_.size(); }
    [[nodiscard]] const std::vector<Photon>& photons() const noexcept { return photons_; }

    /// Irradiance at p on a surface with unit normal n, from the K nearest photons
    /// (Jensen 1996, eq. 6 with a diffuse BRDF taken out): E = sum of the powers of
    /// those arriving on n's side, over the disk pi r^2 that reaches the Kth. Shadow
    /// photons carry no power and are left out of the count. Calibrated: each photon
    /// carries power / photons emitted, so the estimate does not depend on the count.
    template <std::size_t K>
    [[nodiscard]] Rgb<float> irradiance(const Vec3<float>& p, const Vec3<float>& n) const noexcept
    {
        if (!tree_ || photons_.empty()) return Rgb<float>(0.0f);
        const auto found = tree_->nearest<K>({p.x, p.y, p.z});
        Rgb<float> sum(0.0f);
        for (const Neighbour<float>& neighbour : found) {
            const Photon& photon = photons_[neighbour.index];
            if (dot(photon.from, n) > 0.0f) sum += photon.power;
        }
        const float r2 = found[found.size() - 1].distance2;
        return r2 > 0.0f ? sum / (pi<float> * r2) : Rgb<float>(0.0f);
    }

    /// The same within a fixed radius: E = sum of the powers within r over pi r^2,
    /// leaving out photons with any of the `excluded` flags.
    [[nodiscard]] Rgb<float> irradiance_within(const Vec3<float>& p, const Vec3<float>& n, float radius,
                                               std::uint8_t excluded = 0) const noexcept
    {
        Rgb<float> sum(0.0f);
        if (!tree_ || !(radius > 0.0f)) return sum;
        tree_->within({p.x, p.y, p.z}, radius, [&](std::uint32_t index, float) {
            const Photon& photon = photons_[index];
            if ((photon.flags & excluded) == 0 && dot(photon.from, n) > 0.0f) sum += photon.power;
        });
        return sum / (pi<float> * radius * radius);
    }

    /// Precompute irradiance at every `stride`-th photon from its K nearest (Christensen
    /// 1999, "Faster Photon Map Global Illumination"), so that a final-gather ray needs
    /// one nearest-neighbour lookup instead of a density estimate.
    template <std::size_t K>
    void precompute_irradiance(std::size_t stride)
    {
        std::vector<Photon> samples;
        irradiance_.clear();
        for (std::size_t i = 0; i < photons_.size(); i += std::max<std::size_t>(stride, 1)) {
            const Photon& photon = photons_[i];
            if (photon.flags & Photon::shadow) continue;
            samples.push_back(photon);
            irradiance_.push_back(irradiance<K>(photon.position, photon.from));
        }
        samples_ = std::move(samples);
        sample_tree_.emplace(PhotonPositions{samples_});
    }

    /// The precomputed irradiance nearest p among samples that arrived from n's side
    /// (zero when there are none near).
    [[nodiscard]] Rgb<float> precomputed_irradiance(const Vec3<float>& p, const Vec3<float>& n) const noexcept
    {
        if (!sample_tree_ || samples_.empty()) return Rgb<float>(0.0f);
        for (const Neighbour<float>& neighbour : sample_tree_->nearest<4>({p.x, p.y, p.z}))
            if (dot(samples_[neighbour.index].from, n) > 0.0f) return irradiance_[neighbour.index];
        return Rgb<float>(0.0f);
    }

    /// How many of the K nearest photons are direct, and how many are shadow photons
    /// (Jensen and Christensen 1995: all direct means lit, all shadow means in shadow).
    template <std::size_t K>
    [[nodiscard]] std::pair<std::size_t, std::size_t> direct_and_shadow(const Vec3<float>& p) const noexcept
    {
        std::size_t direct = 0, shadow = 0;
        if (!tree_ || photons_.empty()) return {0, 0};
        for (const Neighbour<float>& neighbour : tree_->nearest<K>({p.x, p.y, p.z})) {
            const std::uint8_t flags = photons_[neighbour.index].flags;
            direct += (flags & Photon::direct) != 0;
            shadow += (flags & Photon::shadow) != 0;
        }
        return {direct, shadow};
    }

private:
    std::vector<Photon> photons_;
    std::optional<Tree> tree_;
    std::vector<Photon> samples_;         ///< photons at which irradiance was precomputed
    std::vector<Rgb<float>> irradiance_;  ///< their irradiance
    std::optional<Tree> sample_tree_;
};

} // namespace prism
