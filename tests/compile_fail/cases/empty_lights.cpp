// A scene without any light (no Lights and no emitting object): one error, at this line.
#include <prism/prism.hpp>

int main()
{
    const prism::Scene scene{prism::Lights{}, prism::Object{prism::Sphere<float>({0, 0, 0}, 1), prism::Diffuse<float>{}}}; // line 6
    const prism::Whitted integrator(scene);
    return prism::render(prism::Camera<float>{}, integrator, {.width = 8, .height = 8}).width();
}
