// A material that declares a diffuse lobe but has no diffuse(p): one error, at this line.
#include <prism/prism.hpp>

struct Matte {
    using scalar_type = float;
    static constexpr bool has_diffuse = true;
    static constexpr bool reflects = false;
    static constexpr bool transmits = false;
    prism::Rgb<float> albedo{0.5f};
    void validate() const {}
};

int main()
{
    const prism::Scene scene{prism::Lights{prism::PointLight<float>{}}, prism::Object{prism::Sphere<float>({0, 0, 0}, 1), Matte{}}}; // line 15
    const prism::Whitted integrator(scene);
    return prism::render(prism::Camera<float>{}, integrator, {.width = 8, .height = 8}).width();
}
