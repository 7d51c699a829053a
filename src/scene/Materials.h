#pragma once
// The materials, the BSDFs a finish selects (Finish::material, scene/Scene.h), each described
// once in SCENE_MATERIALS: its name, the #define that compiles its BSDF into a shader (none
// for the Lambertian, which every shader has: it is the fallback of the dispatchers), the
// prefix of its GLSL functions, and whether it scatters into a single direction. The enum,
// the shaders' codes (MATERIAL_<KIND>, as generated #defines), the feature switches, the
// shaders' dispatchers over materials (shadergen/KindDispatchers.cpp) and the names in
// `--features` all come from this list.
//
// Adding a material: a row here, its selection in Finish::material(), and its BSDF in
// shaders/modules/materials.glsl: <prefix>Sample, and for a material that is not a delta
// <prefix>Evaluate and <prefix>Pdf, with the signatures the others have.
// tests/scene/KindTablesTest.cpp walks every row.
#include <string>
#include <vector>

namespace scene {

//  X(kind, name, feature switch or nullptr, GLSL prefix, scattering), in code order
#define SCENE_MATERIALS(X)                                                           \
    X(Lambertian, "lambertian", nullptr, "lambertian", Scattering::Spread)           \
    X(BlinnPhong, "blinn-phong", "HAS_BLINN_PHONG", "blinnPhong", Scattering::Spread) \
    X(Mirror, "mirror", "HAS_MIRROR", "mirror", Scattering::Delta)                   \
    X(Dielectric, "dielectric", "HAS_DIELECTRIC", "dielectric", Scattering::Delta)

// Delta: a single direction for each incoming one (mirror, glass), which no light sample
// can reach; such a BSDF has no evaluation and no density, only a sample.
enum class Scattering { Spread, Delta };

enum class MaterialKind {
#define SCENE_MATERIAL_ENUMERATOR(kind, ...) kind,
    SCENE_MATERIALS(SCENE_MATERIAL_ENUMERATOR)
#undef SCENE_MATERIAL_ENUMERATOR
};

struct MaterialDescription {
    MaterialKind kind;
    int code;                   // its place in the list; the shaders' MATERIAL_<IDENTIFIER>
    const char* identifier;     // the enumerator's name
    const char* name;
    const char* featureSwitch;  // 1 where the shader has the BSDF; nullptr: always there
    const char* glslPrefix;     // its functions <prefix>Sample, <prefix>Evaluate, <prefix>Pdf
    Scattering scattering;
};

// Every material, in code order.
const std::vector<MaterialDescription>& materialDescriptions();
const MaterialDescription& describe(MaterialKind kind);
// The shaders' name for a material's code: MATERIAL_ and the identifier in capitals.
std::string codeName(const MaterialDescription& description);

}  // namespace scene
