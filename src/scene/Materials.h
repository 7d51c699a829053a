#pragma once
// The materials, the BSDFs a finish selects (Finish::material, scene/Scene.h), each described
// once in SCENE_MATERIALS: its name, the keyword that writes it in a scene file (none for the
// classic materials, which the seven numbers of a classic finish select), how the numbers
// after that keyword are read, the #define that compiles its BSDF into a shader (none for
// the Lambertian, which every shader has: it is the fallback of the dispatchers), the prefix
// of its GLSL functions, whether it scatters into a single direction, and whether it is a
// microfacet model (GGX, with a roughness: shaders/modules/microfacet.glsl). The enum, the
// parser's finish keywords, the shaders' codes (MATERIAL_<KIND>, as generated #defines), the
// feature switches, the shaders' dispatchers over materials (shadergen/KindDispatchers.cpp)
// and the names in `--features` all come from this list.
//
// Adding a material: a row here (with its reader in Materials.cpp if it has a keyword), its
// selection in Finish::material() if it has none, and its BSDF in
// shaders/modules/materials.glsl: <prefix>Sample, and for a material that is not a delta
// <prefix>Evaluate and <prefix>Pdf, with the signatures the others have.
// tests/scene/KindTablesTest.cpp walks every row.
#include "scene/TokenCursor.h"

#include <string>
#include <vector>

namespace scene {

struct Finish;

//  X(kind, name, keyword or nullptr, reader or nullptr, feature switch or nullptr, GLSL prefix,
//    scattering, model), in code order
#define SCENE_MATERIALS(X)                                                                         \
    X(Lambertian, "lambertian", nullptr, nullptr, nullptr, "lambertian", Scattering::Spread,       \
      Model::Classic)                                                                              \
    X(BlinnPhong, "blinn-phong", nullptr, nullptr, "HAS_BLINN_PHONG", "blinnPhong",                \
      Scattering::Spread, Model::Classic)                                                          \
    X(Mirror, "mirror", nullptr, nullptr, "HAS_MIRROR", "mirror", Scattering::Delta,               \
      Model::Classic)                                                                              \
    X(Dielectric, "dielectric", nullptr, nullptr, "HAS_DIELECTRIC", "dielectric",                  \
      Scattering::Delta, Model::Classic)                                                           \
    X(RoughConductor, "rough-conductor", "rough_conductor", readRoughConductor,                    \
      "HAS_ROUGH_CONDUCTOR", "roughConductor", Scattering::Spread, Model::Microfacet)              \
    X(RoughDielectric, "rough-dielectric", "rough_dielectric", readRoughDielectric,                \
      "HAS_ROUGH_DIELECTRIC", "roughDielectric", Scattering::Spread, Model::Microfacet)

// Delta: a single direction for each incoming one (mirror, glass), which no light sample
// can reach; such a BSDF has no evaluation and no density, only a sample.
enum class Scattering { Spread, Delta };

// Microfacet: a GGX surface of roughness alpha (Finish::roughness), whose shaders need
// shaders/modules/microfacet.glsl (HAS_MICROFACET).
enum class Model { Classic, Microfacet };

// Reads the numbers after a finish's keyword into `finish`; `which` names the finish in
// messages.
using FinishReader = void (*)(TokenCursor& in, const std::string& which, Finish& finish);

enum class MaterialKind {
#define SCENE_MATERIAL_ENUMERATOR(kind, ...) kind,
    SCENE_MATERIALS(SCENE_MATERIAL_ENUMERATOR)
#undef SCENE_MATERIAL_ENUMERATOR
};

struct MaterialDescription {
    MaterialKind kind;
    int code;                // its place in the list; the shaders' MATERIAL_<IDENTIFIER>
    const char* identifier;  // the enumerator's name
    const char* name;
    const char* keyword;        // the finish's first word in a scene file; nullptr: classic
    FinishReader read;          // the numbers after the keyword; nullptr: classic
    const char* featureSwitch;  // 1 where the shader has the BSDF; nullptr: always there
    const char* glslPrefix;     // its functions <prefix>Sample, <prefix>Evaluate, <prefix>Pdf
    Scattering scattering;
    Model model;
};

// Every material, in code order.
const std::vector<MaterialDescription>& materialDescriptions();
const MaterialDescription& describe(MaterialKind kind);
// The material a finish keyword names, or nullptr (classic finishes start with a number).
const MaterialDescription* findFinishKeyword(const std::string& keyword);
// "rough_conductor or rough_dielectric": every finish keyword, for messages.
std::string finishKeywords();
// The shaders' name for a material's code: MATERIAL_ and the identifier in capitals.
std::string codeName(const MaterialDescription& description);

}  // namespace scene
