// SPDX-License-Identifier: MIT
// An OBJ model with its materials: the meshes of each `usemtl`, and each .mtl material
// mapped onto prism's by one documented rule.
//
// load_obj_model reads the OBJ (as load_obj does: bounded and strict), the material
// library its `mtllib` names (beside it; bounded and strict: every statement is one this
// reader reads, or one it knows and lists in ObjModel::notes as not read), and the
// textures the library names (io/texture.hpp). The rule, per material:
//
// - glass where d < 1 (or Tr > 0) or illum is 4, 6, 7 or 9: a Dielectric of index Ni (1.5
//   where Ni is not given);
// - otherwise an ObjSurface: normalised modified Phong (Lafortune and Willems 1994, the
//   model whose exponent Ns is), its diffuse albedo Kd times map_Kd (an sRGB colour
//   image), its specular albedo Ks times the mean of map_Ks (Phong's specular albedo is
//   one colour: the note says so), exponent Ns; where Kd + Ks would exceed 1 in a channel
//   both are scaled down together to 1 (energy; the note says by how much); a bump map
//   (map_Bump or bump, -bm m: heights of m x ObjOptions::bump_scale scene units) or a
//   tangent-space normal map (norm), read as data (linear).
//
// Faces without a material (no usemtl) get the default material, a grey Lambertian
// ObjSurface (Kd 0.8).
//
// Opt-in, as io/mesh.hpp is (tinyobjloader) and io/texture.hpp (stb_image).
#pragma once

#include <prism/core/check.hpp>
#include <prism/geometry/triangle_mesh.hpp>
#include <prism/io/mesh.hpp>
#include <prism/io/texture.hpp>
#include <prism/material/dielectric.hpp>
#include <prism/material/normal_map.hpp>
#include <prism/material/phong.hpp>
#include <prism/scene/object.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace prism {

/// The opaque material of an OBJ model: Phong with an image for its diffuse albedo, and
/// a bump map or a normal map where the .mtl gives one.
template <Scalar T = float>
struct ObjSurface : Phong<T, ImageTexture<T>> {
    /// It reads surface coordinates (its textures and maps).
    static constexpr bool reads_coordinates = true;

    ImageTexture<T> bump{}; ///< heights (empty: none)
    T bump_scale = T(0);    ///< scene units per unit of height
    ImageTexture<T> normal_map{}; ///< tangent-space normals as RGB (empty: none)

    /// The crossing with its shading normal tilted by the normal map, or moved by the bump map.
    void shade(Crossing<T>& c) const noexcept
    {
        if (!c.has_uv()) return;
        if (normal_map.levels() > 0) detail::apply_normal_map(c, albedo_at(normal_map, texture_point(c)), T(1));
        else if (bump.levels() > 0 && bump_scale > T(0)) detail::apply_bump_map(c, bump, bump_scale, detail::bump_step(bump, T(0)));
    }

    /// Throws std::invalid_argument for a bad Phong part, or a bump scale that is negative or not finite.
    void validate() const
    {
        Phong<T, ImageTexture<T>>::validate();
        detail::require_non_negative("ObjSurface bump_scale", bump_scale);
    }
};

/// How load_obj_model reads a model.
struct ObjOptions {
    double bump_scale = 0.01;  ///< scene units of height per unit of a bump map's value (times its -bm)
    TextureSampling sampling{}; ///< how every texture is read
    ReadLimits limits{};        ///< for the OBJ, the .mtl and each texture
    /// Let `mtllib` and texture names be absolute paths or climb out of the model's folder
    /// with `..` (a model from a source trusted with the whole file system). Off, each
    /// names a file in the folder of the file naming it, or below.
    bool any_path = false;
};

/// An OBJ model: its opaque and its glass parts, a mesh each with its material, and what
/// the reader did not read.
template <Scalar T = float>
struct ObjModel {
    ObjectArray<TriangleMesh<T>, ObjSurface<T>> opaque;   ///< one object per opaque material used
    ObjectArray<TriangleMesh<T>, Dielectric<T>> glass;    ///< one object per glass material used
    std::vector<std::string> notes; ///< what the .mtl holds that the rule does not read, or changed (scaled albedos)
};

namespace detail {

/// The file `name` (a .mtl's or an OBJ's statement `what`) beside `from`: refused through
/// `fail` when absolute or climbing out with `..`, unless `any_path`.
template <class Fail>
[[nodiscard]] std::filesystem::path beside(const std::filesystem::path& from, const std::string& name, const char* what, bool any_path, Fail&& fail)
{
    const std::filesystem::path relative(name);
    bool climbs = false;
    for (const auto& part : relative) climbs = climbs || part == "..";
    if (!any_path && (relative.is_absolute() || relative.has_root_name() || relative.has_root_directory() || climbs))
        fail(std::string("'") + what + "' names '" + printable(name.substr(0, 256)) +
             "': a file must be in the model's folder or below it, not an absolute path or one climbing out with .. (ObjOptions::any_path allows it)");
    return from.parent_path() / relative;
}

/// One material of a .mtl file, as written.
struct MtlMaterial {
    std::string name;
    std::size_t line = 0;
    Rgb<double> kd{0.8}, ks{0.0};
    double ns = 0, ni = 1.5, d = 1;
    int illum = 2;
    std::string map_kd, map_ks, bump, norm;
    double bump_multiplier = 1;
    bool glass() const { return d < 1 || illum == 4 || illum == 6 || illum == 7 || illum == 9; }
};

/// Reads a .mtl file: strict (each number finite, each statement one it knows), its
/// texture names resolved beside it; what it knows but does not read goes to `notes`.
inline std::vector<MtlMaterial> read_mtl(const std::filesystem::path& path, ReadLimits limits, bool any_path, std::vector<std::string>& notes, std::string& text)
{
    InputFile file(path, "material library", limits);
    std::vector<MtlMaterial> out;
    std::size_t number = 0;
    while (const std::optional<std::string> line = file.line(std::size_t(1) << 16, "line " + std::to_string(number + 1))) {
        ++number;
        text += *line;
        text += '\n';
        std::istringstream words(*line);
        std::string keyword;
        words >> keyword;
        if (keyword.empty() || keyword[0] == '#') continue;
        const std::string where = "line " + std::to_string(number) + ": ";
        const auto fail = [&](const std::string& reason) { file.fail(where + reason); };
        const auto number_of = [&](const char* what) {
            std::string w;
            if (!(words >> w)) fail(std::string("'") + what + "' needs a number");
            char* end = nullptr;
            const double v = std::strtod(w.c_str(), &end);
            if (end != w.c_str() + w.size() || !std::isfinite(v) || !std::isfinite(float(v)))
                fail(std::string("'") + what + "' has '" + w.substr(0, 32) + "', not a finite number");
            return v;
        };
        const auto colour = [&](const char* what) {
            std::vector<double> v{number_of(what)};
            while (words >> std::ws && !words.eof()) v.push_back(number_of(what));
            if (v.size() != 1 && v.size() != 3) fail(std::string("'") + what + "' has " + std::to_string(v.size()) + " numbers: give one or three");
            if (v.size() == 1) v = {v[0], v[0], v[0]};
            if (v[0] < 0 || v[1] < 0 || v[2] < 0) fail(std::string("'") + what + "' must not be negative");
            return Rgb<double>{v[0], v[1], v[2]};
        };
        // A texture statement: options (-bm m for bump maps), then the file name.
        const auto texture = [&](const char* what, double* multiplier) {
            std::string w, name;
            while (words >> w) {
                if (w == "-bm" && multiplier != nullptr) {
                    *multiplier = number_of("-bm");
                } else if (!w.empty() && w[0] == '-' && name.empty()) {
                    fail(std::string("'") + what + "' has the option '" + w.substr(0, 16) + "', which prism does not read (only -bm, on a bump map)");
                } else {
                    name += name.empty() ? w : " " + w;
                }
            }
            if (name.empty()) fail(std::string("'") + what + "' names no file");
            return beside(path, name, what, any_path, fail).string();
        };
        if (keyword == "newmtl") {
            MtlMaterial m;
            std::string more;
            if (!(words >> m.name)) fail("'newmtl' needs a name");
            if (words >> more) fail("the material name '" + m.name + " " + more.substr(0, 16) + "...' has a space (tinyobjloader would read only its first word)");
            m.line = number;
            out.push_back(m);
            continue;
        }
        if (out.empty()) fail("'" + printable(keyword.substr(0, 32)) + "' comes before any 'newmtl'");
        MtlMaterial& m = out.back();
        // A statement of one number: that number and nothing after it.
        const auto only_number = [&](const char* what) {
            const double v = number_of(what);
            if (std::string more; words >> more) fail(std::string("'") + what + "' has '" + more.substr(0, 32) + "' after its number");
            return v;
        };
        if (keyword == "Kd") m.kd = colour("Kd");
        else if (keyword == "Ks") m.ks = colour("Ks");
        else if (keyword == "Ns") m.ns = only_number("Ns");
        else if (keyword == "Ni") m.ni = only_number("Ni");
        else if (keyword == "d") m.d = only_number("d");
        else if (keyword == "Tr") m.d = 1 - only_number("Tr");
        else if (keyword == "illum") {
            const double illum = only_number("illum");
            if (!(illum >= 0 && illum <= 10 && illum == std::floor(illum))) fail("'illum' must be a whole number from 0 to 10, got " + std::to_string(illum));
            m.illum = int(illum);
        }
        else if (keyword == "map_Kd") m.map_kd = texture("map_Kd", nullptr);
        else if (keyword == "map_Ks") m.map_ks = texture("map_Ks", nullptr);
        else if (keyword == "map_Bump" || keyword == "map_bump" || keyword == "bump") m.bump = texture("bump", &m.bump_multiplier);
        else if (keyword == "norm" || keyword == "map_Kn") m.norm = texture("norm", nullptr);
        else if (keyword == "Ka" || keyword == "Ke" || keyword == "Tf" || keyword == "map_Ka" || keyword == "map_d" || keyword == "map_Ke" || keyword == "map_Ns" ||
                 keyword == "sharpness" || keyword == "disp" || keyword == "decal" || keyword == "refl" || keyword == "Pr" || keyword == "Pm" || keyword == "Ps" ||
                 keyword == "Pc" || keyword == "Pcr" || keyword == "aniso" || keyword == "anisor")
            notes.push_back(path.filename().string() + " " + where + "'" + keyword + "' of material '" + m.name + "' is not read");
        else fail("'" + printable(keyword.substr(0, 32)) + "' is not a .mtl statement prism knows");
        // (std::to_string's six decimals would show 1e-45 as 0.)
        const auto shown = [](double v) {
            std::string digits;
            append_part(digits, v);
            return digits;
        };
        if (!(m.ns >= 0 && m.ns <= detail::greatest_lobe_exponent))
            fail("'Ns' must be from 0 to 1e6 (a sharper highlight is a mirror), got " + shown(m.ns));
        if (!(m.ni >= detail::least_index && m.ni <= detail::greatest_index)) fail("'Ni' must be an index of refraction from 0.01 to 100, got " + shown(m.ni));
        if (m.d < 0 || m.d > 1) fail("'d' (or 1 - Tr) must be in [0, 1], got " + std::to_string(m.d));
    }
    return out;
}

/// The largest value of any channel of a texture, or of a colour.
template <Scalar T>
Rgb<T> texture_mean(const ImageTexture<T>& t)
{
    const auto& last = t.level(t.levels() - 1).texels;
    return t.channels() == 3 ? Rgb<T>(T(last[0]), T(last[1]), T(last[2])) : Rgb<T>(T(last[0]));
}

} // namespace detail

/// The model in the OBJ file at `path` with its materials (the rule above). Throws
/// std::runtime_error naming the file and line for what cannot be read, and a material
/// that cannot be made (naming the material).
template <Scalar T = float>
[[nodiscard]] ObjModel<T> load_obj_model(const std::filesystem::path& path, ObjOptions options = {})
try {
    ObjModel<T> model;
    // The material library: the first mtllib statement's file, beside the OBJ.
    std::vector<detail::MtlMaterial> materials;
    std::string mtl_text;
    {
        detail::InputFile scan(path, "mesh", options.limits);
        while (const std::optional<std::string> line = scan.line(std::size_t(1) << 20, "a line")) {
            std::istringstream words(*line);
            std::string keyword, name;
            words >> keyword;
            if (keyword != "mtllib") continue;
            std::getline(words >> std::ws, name);
            const auto refuse = [&](const std::string& reason) { scan.fail(reason); };
            materials = detail::read_mtl(detail::beside(path, name, "mtllib", options.any_path, refuse), options.limits, options.any_path, model.notes, mtl_text);
            break;
        }
    }
    detail::InputFile file(path, "mesh", options.limits);
    const tinyobj::ObjReader reader = detail::parse_obj(file, mtl_text);
    // A usemtl naming no material of the library would silently get the default one.
    // (A bare usemtl, "material [ '' ]", is none: the default.)
    std::istringstream warnings(reader.Warning());
    for (std::string warning; std::getline(warnings, warning);)
        if (warning.find("not found") != std::string::npos && warning.find("[ '' ]") == std::string::npos) file.fail("tinyobjloader: " + warning);
    const auto& attrib = reader.GetAttrib();
    const std::size_t positions = attrib.vertices.size() / 3, normals = attrib.normals.size() / 3, uvs = attrib.texcoords.size() / 2;
    // tinyobjloader numbers the materials as the library lists them.
    if (reader.GetMaterials().size() != materials.size())
        file.fail("tinyobjloader read " + std::to_string(reader.GetMaterials().size()) + " materials from its library, prism " + std::to_string(materials.size()));
    // One mesh per material used (-1: none), each vertex (position, normal, uv) once.
    struct Part {
        MeshBuffers<T> mesh;
        std::map<std::array<int, 3>, std::uint32_t> vertex_of;
        bool with_normals = true, with_uvs = true;
    };
    std::map<int, Part> parts;
    for (const auto& shape : reader.GetShapes())
        for (std::size_t f = 0; f < shape.mesh.material_ids.size(); ++f) {
            Part& part = parts[shape.mesh.material_ids[f]];
            for (std::size_t k = 0; k < 3; ++k) {
                const tinyobj::index_t& corner = shape.mesh.indices[3 * f + k];
                if (corner.vertex_index < 0 || std::size_t(corner.vertex_index) >= positions)
                    file.fail("a face refers to vertex " + std::to_string(corner.vertex_index) + " of " + std::to_string(positions));
                part.with_normals = part.with_normals && corner.normal_index >= 0 && std::size_t(corner.normal_index) < normals;
                part.with_uvs = part.with_uvs && corner.texcoord_index >= 0 && std::size_t(corner.texcoord_index) < uvs;
            }
        }
    for (const auto& shape : reader.GetShapes())
        for (std::size_t f = 0; f < shape.mesh.material_ids.size(); ++f) {
            Part& part = parts[shape.mesh.material_ids[f]];
            std::array<std::uint32_t, 3> triangle{};
            for (std::size_t k = 0; k < 3; ++k) {
                const tinyobj::index_t& corner = shape.mesh.indices[3 * f + k];
                const std::array<int, 3> key{corner.vertex_index, part.with_normals ? corner.normal_index : -1, part.with_uvs ? corner.texcoord_index : -1};
                const auto [at, fresh] = part.vertex_of.try_emplace(key, std::uint32_t(part.mesh.positions.size()));
                if (fresh) {
                    const std::size_t v = 3 * std::size_t(key[0]);
                    part.mesh.positions.push_back({T(attrib.vertices[v]), T(attrib.vertices[v + 1]), T(attrib.vertices[v + 2])});
                    if (part.with_normals) {
                        const std::size_t n = 3 * std::size_t(key[1]);
                        const Vec3<T> normal(T(attrib.normals[n]), T(attrib.normals[n + 1]), T(attrib.normals[n + 2]));
                        if (!is_finite(normal) || !(length(Vec3<double>(normal)) > 0)) file.fail("normal " + std::to_string(key[1] + 1) + " is " + detail::describe(normal));
                        part.mesh.normals.push_back(normal);
                    }
                    if (part.with_uvs) part.mesh.uvs.push_back({T(attrib.texcoords[2 * std::size_t(key[2])]), T(attrib.texcoords[2 * std::size_t(key[2]) + 1])});
                }
                triangle[k] = at->second;
            }
            part.mesh.triangles.push_back(triangle);
        }
    if (parts.empty()) file.fail("it has no faces");
    TextureFile colour{.encoding = TextureEncoding::srgb, .channels = 3, .sampling = options.sampling, .limits = options.limits};
    TextureFile data{.encoding = TextureEncoding::linear, .channels = 3, .sampling = options.sampling, .limits = options.limits};
    for (auto& [id, part] : parts) {
        const detail::MtlMaterial m = id >= 0 && std::size_t(id) < materials.size() ? materials[std::size_t(id)] : detail::MtlMaterial{.name = "(none)", .line = 0, .kd = Rgb<double>(0.8), .ks = Rgb<double>(0.0), .ns = 0, .ni = 1.5, .d = 1, .illum = 2, .map_kd = {}, .map_ks = {}, .bump = {}, .norm = {}, .bump_multiplier = 1};
        // A material the rule cannot make (a value float cannot hold, a product that
        // overflows) is refused by name.
        try {
            TriangleMesh<T> mesh(part.mesh);
            if (m.glass()) {
                model.glass.items.emplace_back(std::move(mesh), Dielectric<T>{.ior = T(m.ni)});
                continue;
            }
            // Kd times its map, baked into the texels.
            ImageTexture<T> albedo;
            if (m.map_kd.empty()) {
                const std::vector<float> one{float(m.kd.x), float(m.kd.y), float(m.kd.z)};
                albedo = ImageTexture<T>(1, 1, 3, one, options.sampling);
            } else {
                const ImageTexture<float> map = load_texture<float>(m.map_kd, colour);
                const auto& full = map.level(0);
                std::vector<float> texels(full.texels);
                for (std::size_t i = 0; i < texels.size(); ++i) texels[i] *= float(m.kd[int(i % 3)]);
                albedo = ImageTexture<T>(full.width, full.height, 3, texels, options.sampling);
            }
            Rgb<T> specular(m.ks);
            if (!m.map_ks.empty()) {
                specular = specular * detail::texture_mean(load_texture<T>(m.map_ks, colour));
                model.notes.push_back("material '" + m.name + "': map_Ks is read as its mean colour (Phong's specular albedo is one colour)");
            }
            // Energy: Kd + Ks at most 1 in every channel.
            const T most = albedo.max_value() + max_component(specular);
            T scale_down = T(1);
            if (most > T(1)) {
                scale_down = T(1) / most;
                model.notes.push_back("material '" + m.name + "': Kd + Ks reach " + std::to_string(double(most)) + ", scaled down together by " + std::to_string(double(scale_down)) +
                                      " so that it reflects no more than arrives");
                const auto& full = albedo.level(0);
                std::vector<float> texels(full.texels);
                for (float& x : texels) x *= float(scale_down);
                albedo = ImageTexture<T>(full.width, full.height, 3, texels, options.sampling);
                specular = specular * scale_down;
            }
            ObjSurface<T> surface;
            surface.diffuse = std::move(albedo);
            surface.specular = specular;
            surface.exponent = T(m.ns);
            if (!m.norm.empty()) surface.normal_map = load_texture<T>(m.norm, data);
            if (!m.bump.empty()) {
                TextureFile heights = data;
                heights.channels = 1;
                surface.bump = load_texture<T>(m.bump, heights);
                surface.bump_scale = T(m.bump_multiplier * options.bump_scale);
                if (!m.norm.empty()) model.notes.push_back("material '" + m.name + "': both a normal map and a bump map: the normal map is used");
            }
            model.opaque.items.emplace_back(std::move(mesh), std::move(surface));
        } catch (const std::invalid_argument& e) {
            file.fail("material '" + m.name + "' (line " + std::to_string(m.line) + " of its library): " + e.what());
        }
    }
    return model;
} catch (const allocation_error&) {
    throw;
} catch (const std::bad_alloc&) {
    throw detail::out_of_memory(path, "mesh");
}

} // namespace prism
