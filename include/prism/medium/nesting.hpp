// SPDX-License-Identifier: MIT
// Nested dielectrics: the media a ray is inside of, so that water in a glass, an air
// bubble in glass or a glass in water refract with the right n1 / n2 at every interface.
//
// A ray carries the transmissive objects it has entered (a MediumStack). At an
// interface, the medium on the far side is the one the ray is inside of apart from this
// object: the stack's top (or the scene's air, index 1, when it is empty). Overlapping
// volumes resolve by priority (Schmidt and Budge, "Simple Nested Dielectrics in Ray
// Traced Images", JGT 2002): a material may set `priority` (0 by default), and a
// surface of an object whose priority is below that of the medium the ray is in is a
// false interface: the ray passes it unchanged, only noting that it entered or left. So
// water modelled to overlap a glass's inner wall slightly (no coincident surfaces) is
// cut by the glass, which has the higher priority. Among equal priorities the most
// recently entered object is the medium, which is right for properly nested objects.
// What the media do to light on its way (their index, their attenuation) is
// transport/media.hpp's.
#pragma once

#include <array>
#include <concepts>
#include <cstddef>
#include <cstdint>

namespace prism {

/// A material's nesting priority: its `priority` member, or 0.
template <class M>
[[nodiscard]] constexpr int nesting_priority(const M& material) noexcept
{
    if constexpr (requires { { material.priority } -> std::convertible_to<int>; })
        return int(material.priority);
    else
        return 0;
}

/// An object a ray is inside of: where it is in the scene, and its priority.
struct Inside {
    std::uint32_t slot;  ///< the object's scene slot
    std::uint32_t index; ///< the object within its slot
    int priority;        ///< its material's priority
    // (No initializers: MediumStack's array is left uninitialized.)

    /// Whether both name the same object.
    [[nodiscard]] constexpr bool same_object(const Inside& other) const noexcept { return slot == other.slot && index == other.index; }
};

/// The transmissive objects a ray is inside of, at most `capacity` deep (a ray entering
/// more than that many at once forgets the oldest, and is then outside it).
class MediumStack {
public:
    /// The deepest nesting kept.
    static constexpr std::size_t capacity = 8;

    /// In no object. (Written out: `MediumStack{}` would otherwise clear the whole array.)
    constexpr MediumStack() noexcept {}

    /// Whether the ray is inside no transmissive object (in the air).
    [[nodiscard]] constexpr bool empty() const noexcept { return count_ == 0; }
    /// How many objects the ray is inside of.
    [[nodiscard]] constexpr std::size_t size() const noexcept { return count_; }

    /// The medium the ray travels in: the highest priority, the latest entered among equals.
    [[nodiscard]] constexpr const Inside* top() const noexcept
    {
        const Inside* best = nullptr;
        for (std::size_t i = 0; i < count_; ++i)
            if (best == nullptr || items_[i].priority >= best->priority) best = &items_[i];
        return best;
    }

    /// Whether the ray is inside `object`.
    [[nodiscard]] constexpr bool contains(const Inside& object) const noexcept
    {
        for (std::size_t i = 0; i < count_; ++i)
            if (items_[i].same_object(object)) return true;
        return false;
    }

    /// This stack with `object` entered.
    [[nodiscard]] constexpr MediumStack entered(const Inside& object) const noexcept
    {
        MediumStack next = *this;
        if (next.count_ == capacity) next.remove_at(0);
        next.items_[next.count_++] = object;
        return next;
    }

    /// This stack with `object` left (unchanged if the ray was not inside it).
    [[nodiscard]] constexpr MediumStack left(const Inside& object) const noexcept
    {
        MediumStack next = *this;
        for (std::size_t i = next.count_; i-- > 0;)
            if (next.items_[i].same_object(object)) {
                next.remove_at(i);
                break;
            }
        return next;
    }

private:
    constexpr void remove_at(std::size_t i) noexcept
    {
        for (std::size_t j = i + 1; j < count_; ++j) items_[j - 1] = items_[j];
        --count_;
    }

    // (items_ left uninitialized, only the first count_ read: every camera ray starts with
    // an empty stack, and clearing its 96 bytes was a rep stos a ray.)
    std::array<Inside, capacity> items_;
    std::size_t count_ = 0;
};

/// What a ray meeting a transmissive object's surface does there, given the media it is
/// in: whether the interface is real (false: the ray passes it unchanged), and the
/// media beyond it, for a ray that crosses (refracted, or passing a false interface); a
/// reflected ray stays in the current ones. The medium on the object's other side is
/// the current one when entering and the one beyond when leaving (`outside_of`).
struct Interface {
    bool real = true; ///< false: the interface is not real, and the ray passes it unchanged
    MediumStack beyond{}; ///< the media beyond the interface, for a ray that crosses it
};

/// The interface a ray in `media` meets at a surface of `object` (entering or leaving).
[[nodiscard]] constexpr Interface nested_interface(const MediumStack& media, const Inside& object, bool entering) noexcept
{
    Interface result;
    if (entering) {
        result.beyond = media.entered(object);
        const Inside* current = media.top();
        result.real = current == nullptr || current->priority <= object.priority;
        return result;
    }
    result.beyond = media.left(object);
    const Inside* current = media.top();
    // Leaving an object the ray is inside of but that is not its medium (a higher-priority
    // object overlaps it here): false. Leaving one it never entered (the camera started
    // inside it): real, as without nesting.
    result.real = current == nullptr || current->same_object(object) || !media.contains(object);
    return result;
}

/// The object whose medium lies on the far side of a real interface from the object's
/// inside (none: the scene's air): the medium the ray is in when it enters, the one it
/// will be in when it leaves.
[[nodiscard]] constexpr const Inside* outside_of(const MediumStack& media, const Interface& face, bool entering) noexcept
{
    return entering ? media.top() : face.beyond.top();
}

} // namespace prism
