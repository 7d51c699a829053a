#pragma once
// The pigment kinds, each described once in SCENE_PIGMENTS: its keyword in the scene format,
// how the numbers after it are read, the #define that compiles it into a shader (none for
// the solid colour, which every shader has: it is pigmentColor's fallback), and its GLSL
// colour function. The enum, the parser's words, the shaders' codes (PIGMENT_<KIND>, as
// generated #defines), the feature switches and the shaders' pigmentColor
// (shadergen/KindDispatchers.cpp) all come from this list.
//
// Adding a pigment: a row here with its reader below it in Pigments.cpp, and its colour
// function in shaders/modules/pigments.glsl, with the signature the others have (and its
// numbers packed in render/SceneUniforms.cpp).
// tests/scene/KindTablesTest.cpp walks every row.
#include "scene/FileLookup.h"
#include "scene/TokenCursor.h"

#include <glm/glm.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace scene {

//  X(kind, keyword, feature switch or nullptr, reader, GLSL colour function), in code order
#define SCENE_PIGMENTS(X)                                                                          \
    X(Solid, "solid", nullptr, readSolidPigment, "solidPigmentColor")                              \
    X(Checker, "checker", "HAS_CHECKER_PIGMENT", readCheckerPigment, "checkerPigmentColor")        \
    X(Texture, "texmap", "HAS_TEXTURE_PIGMENT", readTexturePigment, "texturePigmentColor")

enum class PigmentKind {
#define SCENE_PIGMENT_ENUMERATOR(kind, ...) kind,
    SCENE_PIGMENTS(SCENE_PIGMENT_ENUMERATOR)
#undef SCENE_PIGMENT_ENUMERATOR
};

struct Pigment {
    PigmentKind kind = PigmentKind::Solid;
    glm::vec3 color{1.0f};              // solid colour, or the checker's first colour
    glm::vec3 secondColor{0.0f};        // checker only
    float size = 1.0f;                  // checker cube edge, or world units per texture tile
    std::string textureName;            // texture only: as written in the file
    std::filesystem::path texturePath;  // texture only: where it was found
    int line = 0;                       // where the pigment is written, for messages
};

// Reads the numbers after a pigment's keyword into `pigment`; `which` names the pigment in
// messages, `lookup` finds texture files.
using PigmentReader = void (*)(TokenCursor& in, const FileLookup& lookup, const std::string& which,
                               Pigment& pigment);

struct PigmentDescription {
    PigmentKind kind;
    int code;                // its place in the list; the shaders' PIGMENT_<IDENTIFIER>
    const char* identifier;  // the enumerator's name
    const char* keyword;
    const char* featureSwitch;  // 1 where the shader has the pigment; nullptr: always there
    PigmentReader read;
    // vec3 NAME(int pigment, vec3 p, vec3 n, float footprint, float offSurface,
    // float uPattern), as pigmentColor (shaders/modules/pigments.glsl says what the arguments
    // are)
    const char* glslFunction;
};

// Every pigment kind, in code order.
const std::vector<PigmentDescription>& pigmentDescriptions();
const PigmentDescription& describe(PigmentKind kind);
// The kind a scene file's word names, or nullptr.
const PigmentDescription* findPigmentKind(const std::string& keyword);
// "solid, checker or texmap": every keyword, for messages.
std::string pigmentKeywords();
// The shaders' name for a pigment kind's code: PIGMENT_ and the identifier in capitals.
std::string codeName(const PigmentDescription& description);

}  // namespace scene
