// A float light in a scene of double objects: one error, at this line.
#include <prism/prism.hpp>

int main()
{
    const prism::Scene scene{prism::Lights{prism::PointLight<float>{}}, prism::Object{prism::Sphere<double>({0, 0, 0}, 1), prism::Diffuse<double>{}}}; // line 6
    const prism::Whitted integrator(scene);
    return prism::render(prism::Camera<double>{}, integrator, {.width = 8, .height = 8}).width();
}
