// SPDX-License-Identifier: MIT
// Transform: an invertible affine map of points, directions and normals.
#pragma once

#include <prism/core/aabb.hpp>
#include <prism/core/check.hpp>
#include <prism/core/lanes.hpp>
#include <prism/core/math.hpp>
#include <prism/core/offset.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

namespace prism {

template <Scalar T>
using Mat4 = glm::mat<4, 4, T, glm::defaultp>;

template <Scalar T>
using Mat3 = glm::mat<3, 3, T, glm::defaultp>;

/// An affine transform with its inverse. Compose with `then`, which applies this
/// transform first and the argument second, as POV-Ray applies transforms in the order
/// they are written: Transform::rotate_x(30).then(Transform::translate({1, 0, 0})).
template <Scalar T = float>
class Transform {
public:
    // Transform Public Methods

    /// The identity.
    Transform() = default;

    /// From an affine 4x4 matrix (GLM, column-major: m[column][row]). Throws
    /// std::invalid_argument for a non-finite, non-affine or singular matrix. Singular
    /// means ill-conditioned for T: the condition number ||L|| ||L^-1|| of the linear
    /// part L (infinity norm, computed in higher precision) is at least 1 / (2 eps), or
    /// the inverse is not representable in T. A flattening such as scale({1e-6, 1, 1}) is
    /// legitimate however small its determinant; scale({0, 1, 1}) is not.
    explicit Transform(const Mat4<T>& m) : m_(m)
    {
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                if (!is_finite(m[c][r])) detail::throw_invalid("Transform matrix must be finite, got ", m[c][r], " at column ", c, " row ", r);
        if (m[0][3] != T(0) || m[1][3] != T(0) || m[2][3] != T(0) || m[3][3] != T(1))
            detail::throw_invalid("Transform matrix must be affine (last row 0 0 0 1)");
        inverse_ = checked_inverse(m);
        abs_inverse_ = absolute(inverse_);
    }

    /// Translation by `offset`.
    [[nodiscard]] static Transform translate(const Vec3<T>& offset)
    {
        detail::require_finite("Transform translate", offset);
        return Transform(glm::translate(Mat4<T>(T(1)), offset));
    }

    /// Scale by factors per axis; a zero factor is a singular transform.
    [[nodiscard]] static Transform scale(const Vec3<T>& factors)
    {
        detail::require_finite("Transform scale", factors);
        return Transform(glm::scale(Mat4<T>(T(1)), factors));
    }

    /// Rotation by `degrees` about `axis`, counter-clockwise looking down the axis
    /// (right-hand rule in prism's right-handed coordinates).
    [[nodiscard]] static Transform rotate(T degrees, const Vec3<T>& axis)
    {
        detail::require_finite("Transform rotate angle", degrees);
        detail::require_nonzero("Transform rotate axis", axis);
        return Transform(glm::rotate(Mat4<T>(T(1)), degrees * pi<T> / T(180), normalize(axis)));
    }
    /// Rotation by `degrees` about x.
    [[nodiscard]] static Transform rotate_x(T degrees) { return rotate(degrees, {T(1), T(0), T(0)}); }
    /// Rotation by `degrees` about y.
    [[nodiscard]] static Transform rotate_y(T degrees) { return rotate(degrees, {T(0), T(1), T(0)}); }
    /// Rotation by `degrees` about z.
    [[nodiscard]] static Transform rotate_z(T degrees) { return rotate(degrees, {T(0), T(0), T(1)}); }

    /// This transform followed by `next`. Throws std::invalid_argument when the product
    /// overflows or is singular (scale(1e12) four times in float).
    [[nodiscard]] Transform then(const Transform& next) const
    {
        const Mat4<T> product = next.m_ * m_;
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                if (!is_finite(product[c][r]))
                    detail::throw_invalid("Transform::then: the composed transform overflows (", product[c][r], " at column ", c, " row ", r, ")");
        return Transform(product);
    }

    /// The inverse transform.
    [[nodiscard]] Transform inverse() const { return Transform(inverse_, m_); }

    /// The 4x4 matrix, acting on column vectors.
    [[nodiscard]] const Mat4<T>& matrix() const noexcept { return m_; }
    /// The inverse's matrix.
    [[nodiscard]] const Mat4<T>& inverse_matrix() const noexcept { return inverse_; }

    /// p transformed as a point.
    [[nodiscard]] Vec3<T> point(const Vec3<T>& p) const noexcept { return affine_point(m_, p); }
    /// v transformed as a direction (no translation).
    [[nodiscard]] Vec3<T> vector(const Vec3<T>& v) const noexcept { return affine_vector(m_, v); }
    /// The box around `box` carried by the transform: around the images of its eight
    /// corners, grown by their rounding and rounded outward. An empty box stays empty; one
    /// unbounded on some axis gives every point.
    [[nodiscard]] Aabb<T> box(const Aabb<T>& box) const noexcept
    {
        if (box.empty()) return box;
        if (!is_finite(box.lo) || !is_finite(box.hi)) return Aabb<T>::universe();
        Aabb<T> out;
        for (int corner = 0; corner < 8; ++corner) {
            const Vec3<T> p{corner & 1 ? box.hi.x : box.lo.x, corner & 2 ? box.hi.y : box.lo.y, corner & 4 ? box.hi.z : box.lo.z};
            const Vec3<T> w = point(p);
            out.lo = component_min(out.lo, w);
            out.hi = component_max(out.hi, w);
        }
        const Vec3<T> pad = gamma<T>(4) * (abs(out.lo) + abs(out.hi));
        return Aabb<T>{out.lo - pad, out.hi + pad}.rounded_out();
    }

    /// The box around the ball of `radius` about `centre` carried by the transform: the
    /// ellipsoid's own box, whose half-width on axis i is the radius times the length of
    /// row i of the linear part (the most that axis gains over the unit ball). Under a
    /// rotation the box around the ball's box's corners is up to sqrt(3) times as wide on
    /// an axis. Worked out in double and rounded outward.
    [[nodiscard]] Aabb<T> sphere_box(const Vec3<T>& centre, T radius) const noexcept
    {
        Aabb<T> out;
        for (int i = 0; i < 3; ++i) {
            double c = double(m_[3][i]), row2 = 0.0;
            for (int j = 0; j < 3; ++j) {
                c += double(m_[j][i]) * double(centre[j]);
                row2 += double(m_[j][i]) * double(m_[j][i]);
            }
            const double half = double(radius) * std::sqrt(row2);
            // (Every term above is within a few parts in 10^16 of its exact value.)
            const double slack = 1e-12 * (std::abs(c) + half);
            out.lo[i] = next_float_down(T(c - half - slack));
            out.hi[i] = next_float_up(T(c + half + slack));
        }
        return out;
    }

    /// p carried back by the inverse.
    [[nodiscard]] Vec3<T> inverse_point(const Vec3<T>& p) const noexcept { return affine_point(inverse_, p); }
    /// v carried back by the inverse (no translation).
    [[nodiscard]] Vec3<T> inverse_vector(const Vec3<T>& v) const noexcept { return affine_vector(inverse_, v); }
    /// A surface normal maps by the inverse transpose (unnormalised).
    [[nodiscard]] Vec3<T> normal(const Vec3<T>& n) const noexcept
    {
        return {dot(Vec3<T>(inverse_[0]), n), dot(Vec3<T>(inverse_[1]), n), dot(Vec3<T>(inverse_[2]), n)};
    }
    /// A transformed normal carried back: by the transpose (unnormalised).
    [[nodiscard]] Vec3<T> inverse_normal(const Vec3<T>& n) const noexcept { return {dot(Vec3<T>(m_[0]), n), dot(Vec3<T>(m_[1]), n), dot(Vec3<T>(m_[2]), n)}; }

    /// The absolute error bound of point(p) for a point p known to within `error` per
    /// axis (pbrt-v4, Transform::operator()(Point3fi)): the incoming error grows by the
    /// matrix, and the matrix product adds gamma(3) of its terms' size.
    [[nodiscard]] Vec3<T> point_error(const Vec3<T>& p, const Vec3<T>& error) const noexcept { return affine_error(m_, p, error); }

    /// The absolute error bound of inverse_point(p) for an exact p: gamma(3) of the
    /// size of the terms, |M^-1| |p| + |translation| (|M^-1| kept from construction).
    [[nodiscard]] Vec3<T> inverse_point_error(const Vec3<T>& p) const noexcept
    {
        return gamma<T>(3) * affine_point(abs_inverse_, abs(p));
    }

private:
    Transform(const Mat4<T>& m, const Mat4<T>& inverse) : m_(m), inverse_(inverse), abs_inverse_(absolute(inverse)) {}

    /// The inverse of an affine matrix, computed in a wider type (double for float, long
    /// double for double), or a clear error when it is singular for T.
    [[nodiscard]] static Mat4<T> checked_inverse(const Mat4<T>& m)
    {
        using W = std::conditional_t<sizeof(T) < sizeof(double), double, long double>;
        W a[3][3];
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) a[r][c] = W(m[c][r]);
        // Scale by the largest entry first: the determinant of a tiny or huge but
        // well-conditioned matrix must not underflow or overflow.
        W largest = 0;
        for (const auto& row : a)
            for (const W x : row) largest = std::max(largest, x < 0 ? -x : x);
        if (!(largest > 0)) detail::throw_invalid("Transform is singular (its linear part is zero)");
        for (auto& row : a)
            for (W& x : row) x /= largest;
        // Inverse of the scaled L by cofactors.
        const W det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                      a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
        W inv[3][3];
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) {
                const int r1 = (c + 1) % 3, r2 = (c + 2) % 3, c1 = (r + 1) % 3, c2 = (r + 2) % 3;
                inv[r][c] = (a[r1][c1] * a[r2][c2] - a[r1][c2] * a[r2][c1]) / det;
            }
        // Condition number in the infinity norm (scale-free).
        W norm = 0, inv_norm = 0;
        for (int r = 0; r < 3; ++r) {
            W row = 0, inv_row = 0;
            for (int c = 0; c < 3; ++c) row += a[r][c] < 0 ? -a[r][c] : a[r][c], inv_row += inv[r][c] < 0 ? -inv[r][c] : inv[r][c];
            norm = std::max(norm, row);
            inv_norm = std::max(inv_norm, inv_row);
        }
        const W condition = norm * inv_norm;
        if (!(det != 0) || !(condition < W(0.5) / W(std::numeric_limits<T>::epsilon())))
            detail::throw_invalid("Transform is singular for this precision (condition number ", double(condition), ", at most ",
                                  0.5 / double(std::numeric_limits<T>::epsilon()), ")");
        Mat4<T> out(T(1));
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) out[c][r] = T(inv[r][c] / largest);
        // The translation of the inverse: -L^-1 t.
        for (int r = 0; r < 3; ++r) {
            W sum = 0;
            for (int c = 0; c < 3; ++c) sum -= (inv[r][c] / largest) * W(m[3][c]);
            out[3][r] = T(sum);
        }
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                if (!is_finite(out[c][r])) detail::throw_invalid("Transform's inverse is not representable (", out[c][r], " at column ", c, " row ", r, ")");
        return out;
    }

    [[nodiscard]] static Mat4<T> absolute(const Mat4<T>& m) noexcept
    {
        Mat4<T> out;
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) out[c][r] = std::abs(m[c][r]);
        return out;
    }

    // The last row of an affine matrix is (0 0 0 1): skip it.
    // (Each component m[0][i] v.x + m[1][i] v.y + m[2][i] v.z, summed in that order, then
    // the translation added: with vector extensions the three at once, a column in each
    // vector, the same operations lane by lane and so the same bits.)
    [[nodiscard]] static Vec3<T> affine_vector(const Mat4<T>& m, const Vec3<T>& v) noexcept
    {
#if PRISM_VECTOR_EXTENSIONS
        typedef T Column __attribute__((vector_size(4 * sizeof(T))));
        static_assert(sizeof(m[0]) == sizeof(Column));
        Column c0, c1, c2, x, y, z;
        __builtin_memcpy(&c0, &m[0], sizeof(Column)), __builtin_memcpy(&c1, &m[1], sizeof(Column)), __builtin_memcpy(&c2, &m[2], sizeof(Column));
        detail::splat(x, v.x), detail::splat(y, v.y), detail::splat(z, v.z);
        const Column r = c0 * x + c1 * y + c2 * z;
        return {r[0], r[1], r[2]};
#else
        return {m[0][0] * v.x + m[1][0] * v.y + m[2][0] * v.z, m[0][1] * v.x + m[1][1] * v.y + m[2][1] * v.z,
                m[0][2] * v.x + m[1][2] * v.y + m[2][2] * v.z};
#endif
    }
    [[nodiscard]] static Vec3<T> affine_point(const Mat4<T>& m, const Vec3<T>& p) noexcept
    {
        return affine_vector(m, p) + Vec3<T>(m[3]);
    }

    [[nodiscard]] static Vec3<T> affine_error(const Mat4<T>& m, const Vec3<T>& p, const Vec3<T>& error) noexcept
    {
        Vec3<T> out;
        for (int r = 0; r < 3; ++r) {
            T carried = T(0), rounding = std::abs(m[3][r]);
            for (int c = 0; c < 3; ++c) {
                carried += std::abs(m[c][r]) * error[c];
                rounding += std::abs(m[c][r] * p[c]);
            }
            out[r] = (gamma<T>(3) + T(1)) * carried + gamma<T>(3) * rounding;
        }
        return out;
    }

    Mat4<T> m_{T(1)};
    Mat4<T> inverse_{T(1)};
    Mat4<T> abs_inverse_{T(1)};
};

} // namespace prism
