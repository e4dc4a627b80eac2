// SPDX-License-Identifier: MIT
// Fuzz target: any bytes as the .mtl library of a small OBJ model (one triangle with uvs,
// under a material named m). load_obj_model refuses them with std::runtime_error, or
// returns the triangle with a material that validates: an ObjSurface whose albedo is
// finite and non-negative with Kd + Ks at most 1, or glass of a positive index.
#include "file.hpp"

#include <prism/io/obj_model.hpp>

#include <cmath>
#include <fstream>
#include <stdexcept>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::filesystem::path mtl = fuzz::as_file(data, size, ".mtl");
    static const std::filesystem::path obj = [&] {
        const std::filesystem::path path = fuzz::process_file(".obj");
        std::ofstream(path) << "mtllib " << mtl.filename().string() << "\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl m\nf 1/1 2/2 3/3\n";
        return path;
    }();
    try {
        const prism::ObjModel<float> model = prism::load_obj_model<float>(obj, {.limits = fuzz::limits});
        FUZZ_CHECK(model.opaque.items.size() + model.glass.items.size() == 1);
        for (const auto& object : model.opaque.items) {
            object.material.validate();
            FUZZ_CHECK(std::isfinite(object.material.diffuse.max_value()) && object.material.diffuse.max_value() + prism::max_component(object.material.specular) <= 1.0001f);
        }
        for (const auto& object : model.glass.items) FUZZ_CHECK(object.material.ior > 0 && std::isfinite(object.material.ior));
    } catch (const std::runtime_error&) {
    } catch (const std::invalid_argument&) {
        // A material the rule cannot make is refused by name, as std::runtime_error: never this.
        FUZZ_CHECK(false);
    }
    return 0;
}
