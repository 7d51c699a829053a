#include "support/RegressionCases.h"

#include "support/TestPaths.h"

namespace testing_support {

namespace {

RegressionCase feature(const std::string& name, const std::string& what)
{
    RegressionCase regressionCase;
    regressionCase.name = name;
    regressionCase.scene = "tests/scenes/" + name + ".in";
    regressionCase.feature = what;
    return regressionCase;
}

RegressionCase classic(int number, const std::string& what)
{
    RegressionCase regressionCase;
    regressionCase.name = "scene" + std::to_string(number);
    regressionCase.scene = "scenes/scene" + std::to_string(number) + ".in";
    regressionCase.feature = what;
    return regressionCase;
}

}  // namespace

const std::vector<RegressionCase>& regressionCases()
{
    static const std::vector<RegressionCase> cases = {
        classic(1, "classic scene 1: every material, textures, a sphere light"),
        classic(2, "classic scene 2: glass and mirrors in a room, four point lights"),
        classic(3, "classic scene 3: the primitives on a glossy floor, a point light"),
        classic(4, "classic scene 4: the torus-knot user SDF before a brick wall"),
        classic(5, "classic scene 5: the CSG user SDF, albedo-3 floor, a sphere light"),
        classic(6, "classic scene 6: the lattice user SDF (smooth CSG) in a Cornell box"),
        classic(7, "classic scene 7: a glass sphere in a Cornell box, caustics"),
        feature("prim_sphere", "the sphere primitive"),
        feature("prim_room", "the polyhedron primitive (a closed room)"),
        feature("prim_box", "the box primitive"),
        feature("prim_torus", "the torus primitive"),
        feature("prim_cone", "the cone primitive"),
        feature("prim_cylinder", "the cylinder primitive"),
        feature("prim_disk", "the disk primitive"),
        feature("prim_rounded_box", "the rounded box primitive"),
        feature("prim_user_sdf", "a user SDF with @bound and @lipschitz"),
        feature("mat_lambertian", "the Lambertian material"),
        feature("mat_mirror", "the mirror material"),
        feature("mat_blinn_phong", "the Blinn-Phong material"),
        feature("mat_dielectric", "the dielectric material"),
        feature("mat_rough_conductor", "the rough conductor (GGX), Schlick's and gold's Fresnel"),
        feature("mat_rough_dielectric", "the rough dielectric (GGX)"),
        feature("camera_lens", "the thin-lens camera (depth of field)"),
        feature("light_point", "point lights"),
        feature("light_sphere", "a spherical area light"),
        feature("env_sky", "the default sky environment"),
        feature("env_constant", "a constant environment"),
        feature("env_none", "no environment"),
        feature("tex_checker", "the checker pigment"),
        feature("tex_image", "image-texture pigments"),
        feature("csg_union", "CSG union"),
        feature("csg_intersection", "CSG intersection"),
        feature("csg_difference", "CSG difference"),
        feature("csg_smooth_union_exp", "exponential smooth union"),
        feature("csg_smooth_union_poly", "polynomial smooth union"),
        feature("csg_smooth_intersection_exp", "exponential smooth intersection"),
        feature("csg_smooth_intersection_poly", "polynomial smooth intersection"),
        feature("csg_smooth_difference_exp", "exponential smooth difference"),
        feature("csg_smooth_difference_poly", "polynomial smooth difference"),
        feature("xf_translate", "the translate transform"),
        feature("xf_rotate", "the rotate transform"),
        feature("xf_scale", "the scale transform"),
    };
    return cases;
}

std::optional<RegressionCase> findRegressionCase(const std::string& name)
{
    for (const RegressionCase& regressionCase : regressionCases())
        if (regressionCase.name == name)
            return regressionCase;
    return std::nullopt;
}

std::filesystem::path scenePath(const RegressionCase& regressionCase)
{
    return sourceDirectory() / regressionCase.scene;
}

std::filesystem::path referencePath(const RegressionCase& regressionCase)
{
    return referencesDirectory() / (regressionCase.name + ".exr");
}

}  // namespace testing_support
