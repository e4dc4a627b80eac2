// SPDX-License-Identifier: MIT
// Graded-index media: air whose index of refraction varies in space (mirages, a setting
// sun flattened by the atmosphere), and the two ways of tracing a ray through it.
//
// A ray in a medium of index n(x) follows the ray equation d/ds (n dx/ds) = grad n.
// With the optical direction T = n dx/ds (a vector of length n) and the parameter t,
// dt = ds / n, it becomes d^2 x / dt^2 = n grad n = grad(n^2) / 2, which Sharma, Kumar
// and Ghatak (1982, "Tracing rays through graded-index media: a new method", Applied
// Optics 21(6)) integrate with a Runge-Kutta-Nystrom step: `sharma_step`. Its error is
// controlled by step doubling in `AdaptiveStepper`. The classic textbook method,
// "divide the air into layers and keep bending the light", is `LayeredMedium`: straight
// segments through flat layers of constant index, refracted by Snell at each boundary.
//
// Index fields are policies (IndexField): a stratified linear n(y), n^2 linear in y
// (whose rays are exact parabolas), an exponential atmosphere, a heated layer over a
// road, and any callable. Stratified fields vary along y (up).
#pragma once

#include <prism/core/check.hpp>
#include <prism/core/math.hpp>
#include <prism/core/ray.hpp>
#include <prism/optics/refract.hpp>

#include <algorithm>
#include <cmath>
#include <concepts>
#include <limits>

namespace prism {

/// An index of refraction that varies in space: `index(p)` and its gradient
/// `gradient(p)`, both finite and the index > 0 wherever a ray goes.
template <class F>
concept IndexField = requires(const F& field, const Vec3<typename F::scalar_type>& p) {
    requires Scalar<typename F::scalar_type>;
    { field.index(p) } -> std::same_as<typename F::scalar_type>;
    { field.gradient(p) } -> std::same_as<Vec3<typename F::scalar_type>>;
    field.validate();
};

// Index Field Policies

/// n(y) = n0 + slope y.
template <Scalar T = double>
struct LinearIndex {
    /// The precision of the field's values.
    using scalar_type = T;
    T n0 = T(1); ///< index at y = 0
    T slope = T(0); ///< dn/dy

    /// The index at p: n0 + slope y.
    [[nodiscard]] constexpr T index(const Vec3<T>& p) const noexcept { return n0 + slope * p.y; }
    /// The index's gradient, (0, slope, 0) everywhere.
    [[nodiscard]] constexpr Vec3<T> gradient(const Vec3<T>&) const noexcept { return {T(0), slope, T(0)}; }
    /// Throws std::invalid_argument, naming the parameter, for n0 <= 0 or a slope that is not finite.
    constexpr void validate() const
    {
        detail::require_positive("LinearIndex n0", n0);
        detail::require_finite("LinearIndex slope", slope);
    }
};

/// n(y)^2 = a + b y (where a + b y > 0): the field whose rays are exact parabolas,
/// y(x) = y0 + tan(theta0) x + b x^2 / (4 K^2) with K = n(y0) cos(theta0).
template <Scalar T = double>
struct LinearSquareIndex {
    /// The precision of the field's values.
    using scalar_type = T;
    T a = T(1); ///< n^2 at y = 0
    T b = T(0); ///< d(n^2)/dy

    /// The index at p: sqrt(a + b y).
    [[nodiscard]] T index(const Vec3<T>& p) const noexcept { return std::sqrt(a + b * p.y); }
    /// The index's gradient: (0, b / 2n, 0).
    [[nodiscard]] Vec3<T> gradient(const Vec3<T>& p) const noexcept { return {T(0), b / (T(2) * index(p)), T(0)}; }
    /// Throws std::invalid_argument, naming the parameter, for a <= 0 or a b that is not finite.
    constexpr void validate() const
    {
        detail::require_positive("LinearSquareIndex a", a);
        detail::require_finite("LinearSquareIndex b", b);
    }
};

/// The standard exponential atmosphere: n(h) = 1 + (n0 - 1) e^(-h / H), h = y - ground.
/// Defaults: sea-level air at 15 C (n0 - 1 = 2.93e-4, visible light) and H = 8.5 km, in
/// metres.
template <Scalar T = double>
struct ExponentialAtmosphere {
    /// The precision of the field's values.
    using scalar_type = T;
    T n0 = T(1.000293); ///< index at the ground
    T scale_height = T(8500); ///< height over which n - 1 falls by e (metres)
    T ground = T(0); ///< height of the ground

    /// The index at p: 1 + (n0 - 1) exp(-(y - ground) / scale_height).
    [[nodiscard]] T index(const Vec3<T>& p) const noexcept { return T(1) + (n0 - T(1)) * std::exp(-(p.y - ground) / scale_height); }
    /// The index's gradient, along y.
    [[nodiscard]] Vec3<T> gradient(const Vec3<T>& p) const noexcept
    {
        return {T(0), -(n0 - T(1)) / scale_height * std::exp(-(p.y - ground) / scale_height), T(0)};
    }
    /// Throws std::invalid_argument, naming the parameter, for n0 or scale_height <= 0 or a ground that is not finite.
    constexpr void validate() const
    {
        detail::require_positive("ExponentialAtmosphere n0", n0);
        detail::require_positive("ExponentialAtmosphere scale_height", scale_height);
        detail::require_finite("ExponentialAtmosphere ground", ground);
    }
};

/// Hot air over a road: n(y) = n_air - drop e^(-(y - ground) / thickness). The air at the
/// road is hotter, so its index is lower by `drop` (about 1e-6 per kelvin: 3e-5 for a
/// road 30 K above the air), and rays grazing it bend back up (an inferior mirage).
template <Scalar T = double>
struct HeatedLayer {
    /// The precision of the field's values.
    using scalar_type = T;
    T n_air = T(1.000293); ///< index of the air far above the ground
    T drop = T(3e-5); ///< how much lower the index is at the ground
    T thickness = T(0.3); ///< metres over which the excess heat falls by e
    T ground = T(0); ///< height of the ground

    /// The index at p: n_air - drop exp(-(y - ground) / thickness).
    [[nodiscard]] T index(const Vec3<T>& p) const noexcept { return n_air - drop * std::exp(-(p.y - ground) / thickness); }
    /// The index's gradient, along y.
    [[nodiscard]] Vec3<T> gradient(const Vec3<T>& p) const noexcept
    {
        return {T(0), drop / thickness * std::exp(-(p.y - ground) / thickness), T(0)};
    }
    /// Throws std::invalid_argument, naming the parameter, for n_air or thickness <= 0, or a drop that is not finite or not below n_air.
    constexpr void validate() const
    {
        detail::require_positive("HeatedLayer n_air", n_air);
        detail::require_finite("HeatedLayer drop", drop);
        if (!(drop < n_air)) detail::throw_invalid("HeatedLayer drop must be below n_air (", n_air, "), got ", drop);
        detail::require_positive("HeatedLayer thickness", thickness);
        detail::require_finite("HeatedLayer ground", ground);
    }
};

/// Any index n(p) given as a callable; its gradient by central differences of step h.
template <Scalar T, class F>
    requires std::regular_invocable<const F&, const Vec3<T>&>
struct IndexFunction {
    /// The precision of the field's values.
    using scalar_type = T;
    F function; ///< n(p), any callable
    T h = T(1e-4); ///< step of the central differences that give the gradient

    /// The index at p: function(p).
    [[nodiscard]] T index(const Vec3<T>& p) const { return function(p); }
    /// The index's gradient by central differences of step h.
    [[nodiscard]] Vec3<T> gradient(const Vec3<T>& p) const
    {
        const T inv = T(1) / (T(2) * h);
        return {(function(p + Vec3<T>(h, 0, 0)) - function(p - Vec3<T>(h, 0, 0))) * inv,
                (function(p + Vec3<T>(0, h, 0)) - function(p - Vec3<T>(0, h, 0))) * inv,
                (function(p + Vec3<T>(0, 0, h)) - function(p - Vec3<T>(0, 0, h))) * inv};
    }
    /// Throws std::invalid_argument for h <= 0.
    constexpr void validate() const { detail::require_positive("IndexFunction h", h); }
};

static_assert(IndexField<LinearIndex<double>> && IndexField<LinearSquareIndex<float>> && IndexField<ExponentialAtmosphere<double>> &&
              IndexField<HeatedLayer<double>>);

// Curved Rays

/// A ray inside a graded medium: where it is, and its optical direction n dx/ds (a
/// vector of length n(position): the unit direction times the local index).
template <Scalar T>
struct CurvedRay {
    Vec3<T> position; ///< where the ray is
    Vec3<T> optical; ///< the optical direction, n times the unit tangent

    /// The unit tangent of the ray.
    [[nodiscard]] Vec3<T> direction() const noexcept { return normalize(optical); }
};

/// The curved ray leaving `ray.origin` along `ray.direction` (any length) in the field.
template <IndexField F>
[[nodiscard]] CurvedRay<typename F::scalar_type> curved_ray(const F& field, const Ray<typename F::scalar_type>& ray) noexcept
{
    return {ray.origin, field.index(ray.origin) * normalize(ray.direction)};
}

/// grad(n^2) / 2 = n grad n: the ray's acceleration in the parameter t (dt = ds / n).
template <IndexField F>
[[nodiscard]] Vec3<typename F::scalar_type> bending(const F& field, const Vec3<typename F::scalar_type>& p) noexcept
{
    return field.index(p) * field.gradient(p);
}

/// One Runge-Kutta-Nystrom step of dt in t (Sharma et al. 1982, eq. 12), fourth order:
///   A = dt D(x), B = dt D(x + dt/2 T + dt/8 A), C = dt D(x + dt T + dt/2 B),
///   x' = x + dt (T + (A + 2B) / 6),  T' = T + (A + 4B + C) / 6,
/// exact when D is constant (n^2 linear in space). The arc length covered is about n dt.
template <IndexField F>
[[nodiscard]] CurvedRay<typename F::scalar_type> sharma_step(const F& field, const CurvedRay<typename F::scalar_type>& ray,
                                                             typename F::scalar_type dt) noexcept
{
    using T = typename F::scalar_type;
    const Vec3<T>& x = ray.position;
    const Vec3<T>& t = ray.optical;
    const Vec3<T> a = dt * bending(field, x);
    const Vec3<T> b = dt * bending(field, x + (dt / T(2)) * t + (dt / T(8)) * a);
    const Vec3<T> c = dt * bending(field, x + dt * t + (dt / T(2)) * b);
    return {x + dt * (t + (a + T(2) * b) / T(6)), t + (a + T(4) * b + c) / T(6)};
}

/// Sharma steps whose length adapts to keep each step's position error under
/// `tolerance` (absolute, in scene units), estimated by step doubling: a step of dt
/// against two of dt / 2, whose difference is 15/16 of the larger one's error for a
/// fourth-order method; the two half steps are kept (Richardson-extrapolated).
template <IndexField F>
class AdaptiveStepper {
public:
    /// The field's precision.
    using T = typename F::scalar_type;

    /// How the stepper controls its error: the tolerance per step and the step sizes it may take.
    struct Config {
        T tolerance = T(1e-6);  ///< position error allowed per step
        T first_step = T(0.1);  ///< the first step's arc length
        T max_step = T(10);     ///< no step longer than this arc length
    };

    /// A stepper through `field` (which must outlive it).
    explicit AdaptiveStepper(const F& field, Config config = {}) : field_(&field), config_(config)
    {
        field.validate();
        detail::require_positive("AdaptiveStepper tolerance", config.tolerance);
        detail::require_positive("AdaptiveStepper first_step", config.first_step);
        detail::require_positive("AdaptiveStepper max_step", config.max_step);
    }

    /// Advance `ray` by one accepted step; `dt` carries the step size from one call to
    /// the next (start with 0: the first step is then config.first_step long). Returns
    /// the arc length covered (about n dt); `accepted`, if given, receives the step's dt.
    T step(CurvedRay<T>& ray, T& dt, T* accepted = nullptr) const noexcept
    {
        const T n = length(ray.optical);
        if (!(dt > T(0))) dt = config_.first_step / n;
        dt = std::min(dt, config_.max_step / n);
        for (;;) {
            const CurvedRay<T> whole = sharma_step(*field_, ray, dt);
            const CurvedRay<T> half = sharma_step(*field_, sharma_step(*field_, ray, dt / T(2)), dt / T(2));
            const T error = length(half.position - whole.position) * (T(16) / T(15));
            const T scale = error > T(0) ? T(0.9) * std::pow(config_.tolerance / error, T(0.2)) : T(4);
            if (error <= config_.tolerance || dt * n <= std::numeric_limits<T>::epsilon() * (T(1) + max_component(abs(ray.position)))) {
                const T covered = length(half.position - ray.position);
                if (accepted != nullptr) *accepted = dt;
                ray = {half.position + (half.position - whole.position) / T(15), half.optical + (half.optical - whole.optical) / T(15)};
                dt *= std::clamp(scale, T(0.2), T(4));
                return covered;
            }
            dt *= std::clamp(scale, T(0.1), T(0.9));
        }
    }

private:
    const F* field_;
    Config config_;
};

// Flat Layers of Constant Index

/// The air between y = bottom and y = top cut into `layers` flat layers, each of the
/// field's index at its middle height; a ray goes straight within a layer and refracts
/// by Snell's law (or reflects totally) at each boundary.
template <IndexField F>
class LayeredMedium {
public:
    /// The field's precision.
    using T = typename F::scalar_type;

    /// `layers` flat layers of `field` between heights `bottom` and `top` (which must outlive it); throws for bottom >= top or layers < 1.
    LayeredMedium(const F& field, T bottom, T top, int layers) : field_(&field), bottom_(bottom), top_(top), layers_(layers)
    {
        field.validate();
        detail::require_finite("LayeredMedium bottom", bottom);
        detail::require_finite("LayeredMedium top", top);
        if (!(top > bottom)) detail::throw_invalid("LayeredMedium top must be above bottom (", bottom, "), got ", top);
        if (layers < 1) detail::throw_invalid("LayeredMedium layers must be >= 1, got ", layers);
        height_ = (top - bottom) / T(layers);
    }

    /// The number of layers.
    [[nodiscard]] int layers() const noexcept { return layers_; }

    /// The layer holding height y (clamped into [0, layers); in floating point first, so a
    /// far-off or NaN height never overflows the conversion to int).
    [[nodiscard]] int layer_of(T y) const noexcept
    {
        const T layer = std::floor((y - bottom_) / height_);
        if (!(layer > T(0))) return 0;
        return layer < T(layers_ - 1) ? static_cast<int>(layer) : layers_ - 1;
    }

    /// The index of layer i: the field at its middle height (x = z = 0: stratified fields).
    [[nodiscard]] T index_of(int layer) const noexcept { return field_->index({T(0), bottom_ + (T(layer) + T(0.5)) * height_, T(0)}); }

    /// From `origin` in layer `layer` along the unit `direction`, straight to the layer's
    /// next boundary and across it (or back, under total internal reflection). Returns
    /// false when the ray leaves the layers (through the top or the bottom) or runs
    /// horizontally; then `origin` is where it left.
    bool step(Vec3<T>& origin, Vec3<T>& direction, int& layer) const noexcept
    {
        if (direction.y == T(0)) return false;
        const bool up = direction.y > T(0);
        const T boundary = bottom_ + T(layer + (up ? 1 : 0)) * height_;
        origin = origin + ((boundary - origin.y) / direction.y) * direction;
        origin.y = boundary;
        const int next = layer + (up ? 1 : -1);
        if (next < 0 || next >= layers_) return false;
        const Vec3<T> facing{T(0), up ? T(-1) : T(1), T(0)};
        if (const auto r = refraction(direction, facing, index_of(next) / index_of(layer))) {
            direction = normalize(r->direction);
            layer = next;
        } else {
            direction = reflect(direction, facing);
        }
        return true;
    }

private:
    const F* field_;
    T bottom_, top_, height_ = T(1);
    int layers_;
};

} // namespace prism
