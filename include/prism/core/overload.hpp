// SPDX-License-Identifier: MIT
// Overload{f, g, ...}: several callables' call operators as one callable, so one argument
// can take what a caller is shown in several shapes (a walk's on_medium, shown both the
// walk's medium vertices and the stretches it crosses).
#pragma once

namespace prism {

/// The call operators of every F, as one object's overloads.
template <class... F>
struct Overload : F... {
    using F::operator()...;
};
template <class... F>
Overload(F...) -> Overload<F...>;

} // namespace prism
