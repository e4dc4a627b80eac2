// SPDX-License-Identifier: MIT
// prism: physically careful ray tracing as compile-time scene composition.
// Includes everything except io/ (image files need stb_image_write; include
// <prism/io/image.hpp> for them).
#pragma once

#include <prism/accel/kd_tree.hpp>
#include <prism/core/aabb.hpp>
#include <prism/core/check.hpp>
#include <prism/core/config.hpp>
#include <prism/core/interval.hpp>
#include <prism/core/math.hpp>
#include <prism/core/offset.hpp>
#include <prism/core/ray.hpp>
#include <prism/core/rng.hpp>
#include <prism/core/sampling.hpp>
#include <prism/core/transform.hpp>
#include <prism/csg/csg_node.hpp>
#include <prism/csg/difference.hpp>
#include <prism/csg/intersection.hpp>
#include <prism/csg/union.hpp>
#include <prism/geometry/box.hpp>
#include <prism/geometry/crossings.hpp>
#include <prism/geometry/plane.hpp>
#include <prism/geometry/quadric.hpp>
#include <prism/geometry/shape.hpp>
#include <prism/geometry/sphere.hpp>
#include <prism/geometry/transformed.hpp>
#include <prism/integrator/direct.hpp>
#include <prism/integrator/photon_mapper.hpp>
#include <prism/integrator/whitted.hpp>
#include <prism/light/directional_light.hpp>
#include <prism/light/light.hpp>
#include <prism/light/point_light.hpp>
#include <prism/material/conductor.hpp>
#include <prism/material/dielectric.hpp>
#include <prism/material/diffuse.hpp>
#include <prism/material/scattering.hpp>
#include <prism/material/texture.hpp>
#include <prism/material/traits.hpp>
#include <prism/medium/graded_index.hpp>
#include <prism/medium/homogeneous.hpp>
#include <prism/medium/medium.hpp>
#include <prism/optics/beer.hpp>
#include <prism/optics/dispersion.hpp>
#include <prism/optics/fresnel.hpp>
#include <prism/optics/refract.hpp>
#include <prism/photon/photon.hpp>
#include <prism/photon/photon_map.hpp>
#include <prism/photon/photon_tracer.hpp>
#include <prism/render/film.hpp>
#include <prism/render/render.hpp>
#include <prism/scene/camera.hpp>
#include <prism/scene/hit.hpp>
#include <prism/scene/object.hpp>
#include <prism/scene/scene.hpp>
