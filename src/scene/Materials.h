#pragma once
// The materials, the BSDFs a finish selects (Finish::material, scene/Scene.h), each described
// once in SCENE_MATERIALS: its name, and the #define that compiles its BSDF into a shader
// (none for the Lambertian, which every shader has: it is the fallback of the dispatchers).
// The enum, the shaders' codes (MATERIAL_<KIND>, as generated #defines), the feature
// switches and the names in `--features` all come from this list.
//
// Adding a material: a row here, its selection in Finish::material(), and its BSDF and its
// cases in the dispatchers of shaders/modules/materials.glsl. tests/scene/KindTablesTest.cpp
// walks every row.
#include <string>
#include <vector>

namespace scene {

//  X(kind, name, feature switch or nullptr), in code order
#define SCENE_MATERIALS(X)                          \
    X(Lambertian, "lambertian", nullptr)            \
    X(BlinnPhong, "blinn-phong", "HAS_BLINN_PHONG") \
    X(Mirror, "mirror", "HAS_MIRROR")               \
    X(Dielectric, "dielectric", "HAS_DIELECTRIC")

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
};

// Every material, in code order.
const std::vector<MaterialDescription>& materialDescriptions();
const MaterialDescription& describe(MaterialKind kind);
// The shaders' name for a material's code: MATERIAL_ and the identifier in capitals.
std::string codeName(const MaterialDescription& description);

}  // namespace scene
