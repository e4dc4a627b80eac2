// SPDX-License-Identifier: MIT
#include <prism/io/obj_model.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace fs = std::filesystem;
using doctest::Approx;

namespace {

fs::path obj_scratch(const std::string& name)
{
    const fs::path dir = fs::temp_directory_path() / ("prism-obj-model-test-" + name + "-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

void obj_write_text(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

/// Two unit squares at y = 0 (x in [0, 1] and [2, 3]) with uvs, and a triangle above.
const char* const obj_two_squares = R"(mtllib parts.mtl
v 0 0 0
v 1 0 0
v 1 0 -1
v 0 0 -1
v 2 0 0
v 3 0 0
v 3 0 -1
v 2 0 -1
v 0 1 0
v 1 1 0
v 0 1 -1
vt 0 0
vt 1 0
vt 1 1
vt 0 1
usemtl painted
f 1/1 2/2 3/3 4/4
usemtl window_glass
f 5 6 7 8
usemtl
f 9 10 11
)";

} // namespace

TEST_CASE("an OBJ model with its .mtl: a mesh per material, mapped by the rule (Phong with Kd x map_Kd, glass by d, the default grey), notes for what is not read")
{
    const fs::path dir = obj_scratch("parts");
    // A 2 x 2 sRGB picture: top row white and black, bottom row sRGB 128 grey twice.
    const unsigned char texels[12] = {255, 255, 255, 0, 0, 0, 128, 128, 128, 128, 128, 128};
    REQUIRE(stbi_write_png((dir / "paint.png").c_str(), 2, 2, 3, texels, 6) != 0);
    const unsigned char heights[4] = {0, 255, 0, 255}; // rising along u
    REQUIRE(stbi_write_png((dir / "bumps.png").c_str(), 2, 2, 1, heights, 2) != 0);
    obj_write_text(dir / "parts.mtl", R"(# two materials
newmtl painted
Ka 1 1 1
Kd 0.5 0.5 0.5
Ks 0.25
Ns 60
map_Kd paint.png
bump -bm 2 bumps.png
newmtl window_glass
Kd 1 1 1
d 0.2
Ni 1.33
)");
    obj_write_text(dir / "model.obj", obj_two_squares);
    const auto model = prism::load_obj_model<double>(dir / "model.obj", {.bump_scale = 0.5, .sampling = {prism::Wrap::clamp, prism::TextureFilter::nearest}});
    REQUIRE(model.opaque.items.size() == 2);
    REQUIRE(model.glass.items.size() == 1);
    CHECK(model.glass.items[0].material.ior == Approx(1.33));
    CHECK(model.glass.items[0].shape.triangle_count() == 2);
    // The painted square: Kd x the decoded picture; v = 1 is the picture's top row.
    const auto& painted = model.opaque.items[1].material; // materials in the library's order after the default (-1)
    CHECK(model.opaque.items[1].shape.triangle_count() == 2);
    CHECK(painted.diffuse.albedo({{}, {0.25, 0.75}, 0}).x == Approx(0.5));
    CHECK(painted.diffuse.albedo({{}, {0.75, 0.75}, 0}).x == Approx(0));
    CHECK(painted.diffuse.albedo({{}, {0.25, 0.25}, 0}).x == Approx(0.5 * 0.2158605).epsilon(1e-5));
    CHECK(painted.specular.x == Approx(0.25));
    CHECK(painted.exponent == 60);
    CHECK(painted.bump_scale == Approx(1.0)); // -bm 2 x 0.5
    CHECK(painted.bump.channels() == 1);
    // The faces without a material: grey Lambertian.
    CHECK(model.opaque.items[0].shape.triangle_count() == 1);
    CHECK(model.opaque.items[0].material.diffuse.albedo({{}, {0.5, 0.5}, 0}).y == Approx(0.8));
    CHECK(model.opaque.items[0].material.specular.y == 0);
    REQUIRE(model.notes.size() == 1);
    CHECK(model.notes[0].find("'Ka' of material 'painted' is not read") != std::string::npos);
    fs::remove_all(dir);
}

TEST_CASE("an OBJ's mtllib names a file in its folder or below, not an absolute path or one climbing out, unless ObjOptions::any_path")
{
    const fs::path dir = obj_scratch("paths");
    fs::create_directories(dir / "model" / "materials");
    obj_write_text(dir / "outside.mtl", "newmtl painted\nKd 0.5 0.5 0.5\nnewmtl window_glass\nd 0.5\n");
    obj_write_text(dir / "model" / "materials" / "parts.mtl", "newmtl painted\nKd 0.5 0.5 0.5\nnewmtl window_glass\nd 0.5\n");
    const std::string body = std::string(obj_two_squares).substr(std::string(obj_two_squares).find('\n') + 1);
    const auto model_with = [&](const std::string& mtllib) {
        obj_write_text(dir / "model" / "model.obj", "mtllib " + mtllib + "\n" + body);
        return dir / "model" / "model.obj";
    };
    CHECK(prism::load_obj_model<float>(model_with("materials/parts.mtl")).opaque.items.size() == 2);
    CHECK_THROWS_WITH_AS((void)prism::load_obj_model<float>(model_with("../outside.mtl")),
                         doctest::Contains("'mtllib' names '../outside.mtl': a file must be in the model's folder or below it"), std::runtime_error);
    const std::string absolute = (dir / "outside.mtl").string();
    const std::string names_absolute = "'mtllib' names '" + absolute + "'";
    CHECK_THROWS_WITH_AS((void)prism::load_obj_model<float>(model_with(absolute)), doctest::Contains(names_absolute.c_str()), std::runtime_error);
    // Trusted: both read.
    CHECK(prism::load_obj_model<float>(model_with("../outside.mtl"), {.any_path = true}).opaque.items.size() == 2);
    CHECK(prism::load_obj_model<float>(model_with(absolute), {.any_path = true}).opaque.items.size() == 2);
    fs::remove_all(dir);
}

TEST_CASE("a .mtl whose Kd + Ks exceed 1 is scaled down with a note; a bad statement, option or number is refused naming its line")
{
    const fs::path dir = obj_scratch("strict");
    obj_write_text(dir / "model.obj", obj_two_squares);
    obj_write_text(dir / "parts.mtl", "newmtl painted\nKd 0.8 0.8 0.8\nKs 0.5 0.5 0.5\nnewmtl window_glass\nd 0.5\n");
    const auto bright = prism::load_obj_model<float>(dir / "model.obj");
    const auto& painted = bright.opaque.items[1].material;
    CHECK(painted.diffuse.max_value() + painted.specular.x == Approx(1.0f));
    CHECK(painted.diffuse.max_value() / painted.specular.x == Approx(1.6f));
    REQUIRE(bright.notes.size() == 1);
    CHECK(bright.notes[0].find("Kd + Ks reach 1.3") != std::string::npos);
    const auto refused = [&](const std::string& mtl, const std::string& reason) {
        obj_write_text(dir / "parts.mtl", mtl);
        CHECK_THROWS_WITH_AS((void)prism::load_obj_model<float>(dir / "model.obj"), doctest::Contains(reason.c_str()), std::runtime_error);
    };
    refused("newmtl painted\nKd 0.5 0.5 0.5\nshininess 3\n", "line 3: 'shininess' is not a .mtl statement prism knows");
    refused("newmtl painted\nKd 0.5 nan 0.5\n", "line 2: 'Kd' has");
    refused("Kd 0.5\n", "line 1: 'Kd' comes before any 'newmtl'");
    refused("newmtl painted\nmap_Kd -s 2 2 1 paint.png\n", "line 2: 'map_Kd' has the option '-s'");
    refused("newmtl painted\nmap_Kd absent.png\nnewmtl window_glass\nd 0.5\n", "absent.png");
    refused("newmtl painted\nd 1.5\n", "line 2: 'd' (or 1 - Tr) must be in [0, 1]");
    refused("newmtl painted\nKd -1 0 0\n", "line 2: 'Kd' must not be negative");
    refused("newmtl painted\nKd 1 0\n", "line 2: 'Kd' has 2 numbers");
    // Found by the mtl fuzz target: a Kd beyond float made a texel of infinity, refused as
    // std::invalid_argument instead of naming the file.
    refused("newmtl painted\nKd 1e39\n", "line 2: 'Kd' has '1e39', not a finite number");
    // Found by it too: an illum beyond int was converted regardless, and words after a
    // number were dropped.
    refused("newmtl painted\nillum 111111111117\n", "line 2: 'illum' must be a whole number from 0 to 10");
    refused("newmtl painted\nNi 1.3 m\n", "line 2: 'Ni' has 'm' after its number");
    // Regression: Ns 3e38 and Ni 1e-45 passed, and their samples were NaN.
    refused("newmtl painted\nNs 3e38\n", "line 2: 'Ns' must be from 0 to 1e6 (a sharper highlight is a mirror), got 3e+38");
    refused("newmtl painted\nNi 1e-45\n", "line 2: 'Ni' must be an index of refraction from 0.01 to 100, got 1e-45");
    refused("newmtl painted now\n", "line 1: the material name 'painted now...' has a space");
    refused("newmtl painted\n", "window_glass"); // a usemtl naming no material
    // Regression: a texture's name could be absolute or climb out of the model's folder,
    // reaching any file (and a .mtl's error quoted its first line).
    refused("newmtl painted\nmap_Kd ../../etc/paint.png\n",
            "line 2: 'map_Kd' names '../../etc/paint.png': a file must be in the model's folder or below it, not an absolute path or one climbing out with ..");
    refused("newmtl painted\nmap_Kd /etc/paint.png\n", "line 2: 'map_Kd' names '/etc/paint.png'");
    fs::remove(dir / "parts.mtl");
    CHECK_THROWS_WITH_AS((void)prism::load_obj_model<float>(dir / "model.obj"), doctest::Contains("parts.mtl"), std::runtime_error);
    fs::remove_all(dir);
}
