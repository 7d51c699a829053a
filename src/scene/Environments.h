#pragma once
// The environment kinds (the radiance of rays that escape the scene), each described once in
// SCENE_ENVIRONMENTS: its words after `environment` in the scene format, how what follows them
// is read, and the #define that compiles its code into a shader (none for the kinds every
// shader has). The enum, the parser's words, the shaders' codes (ENVIRONMENT_<KIND>, as
// generated #defines) and the feature switches all come from this list.
//
// Adding an environment: a row here with its reader in Environments.cpp, and its radiance in
// shaders/modules/environment.glsl. tests/scene/KindTablesTest.cpp walks every row.
#include "scene/FileLookup.h"
#include "scene/TokenCursor.h"

#include <glm/glm.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace scene {

struct Environment;
// Reads what follows an environment's word into `environment`; `lookup` finds map files.
using EnvironmentReader = void (*)(TokenCursor& in, const FileLookup& lookup,
                                   Environment& environment);

void readNoArguments(TokenCursor& in, const FileLookup& lookup, Environment& environment);
void readEnvironmentColour(TokenCursor& in, const FileLookup& lookup, Environment& environment);
void readEnvironmentMap(TokenCursor& in, const FileLookup& lookup, Environment& environment);

//  X(kind, keyword, another word for it or "", feature switch or nullptr, reader), in code order
#define SCENE_ENVIRONMENTS(X)                                                                      \
    X(None, "none", "black", nullptr, readNoArguments)                                             \
    X(Sky, "sky", "", nullptr, readNoArguments)                                                    \
    X(Constant, "constant", "", nullptr, readEnvironmentColour)                                    \
    X(Map, "map", "", "HAS_ENVIRONMENT_MAP", readEnvironmentMap)

enum class EnvironmentKind {
#define SCENE_ENVIRONMENT_ENUMERATOR(kind, ...) kind,
    SCENE_ENVIRONMENTS(SCENE_ENVIRONMENT_ENUMERATOR)
#undef SCENE_ENVIRONMENT_ENUMERATOR
};

struct Environment {
    EnvironmentKind kind = EnvironmentKind::Sky;
    glm::vec3 color{0.0f};  // Constant only

    // Map only: a latitude-longitude image of radiance (docs/SCENE_FORMAT.md gives its
    // orientation), times `intensity`, turned by `rotationDegrees` about the world's up axis.
    std::string mapName;            // as written in the file
    std::filesystem::path mapPath;  // where it was found
    float intensity = 1.0f;
    float rotationDegrees = 0.0f;
    int line = 0;  // where the environment is written, for messages
    // Not in the scene format: false leaves the map to the rays that escape the scene, as the
    // other environments are (no light sampling), so that what sampling it buys can be
    // measured (bench/environment_sampling.cpp).
    bool importanceSampled = true;
};

struct EnvironmentDescription {
    EnvironmentKind kind;
    int code;                // its place in the list; the shaders' ENVIRONMENT_<IDENTIFIER>
    const char* identifier;  // the enumerator's name
    const char* keyword;
    const char* alias;          // "" for none
    const char* featureSwitch;  // 1 where the shader has the kind's code; nullptr: always there
    EnvironmentReader read;
};

// Every environment kind, in code order.
const std::vector<EnvironmentDescription>& environmentDescriptions();
const EnvironmentDescription& describe(EnvironmentKind kind);
// The kind a scene file's word (its keyword or its alias) names, or nullptr.
const EnvironmentDescription* findEnvironmentKind(const std::string& word);
// The shaders' name for an environment kind's code: ENVIRONMENT_ and the identifier in capitals.
std::string codeName(const EnvironmentDescription& description);

}  // namespace scene
