#pragma once
// The environment kinds (the radiance of rays that escape the scene), each described once in
// SCENE_ENVIRONMENTS: its words after `environment` in the scene format and whether a colour
// follows. The enum, the parser's words and the shaders' codes (ENVIRONMENT_<KIND>, as
// generated #defines) all come from this list.
//
// Adding an environment: a row here and its radiance in shaders/modules/environment.glsl.
// tests/scene/KindTablesTest.cpp walks every row.
#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace scene {

//  X(kind, keyword, another word for it or "", a colour follows), in code order
#define SCENE_ENVIRONMENTS(X)           \
    X(None, "none", "black", false)     \
    X(Sky, "sky", "", false)            \
    X(Constant, "constant", "", true)

enum class EnvironmentKind {
#define SCENE_ENVIRONMENT_ENUMERATOR(kind, ...) kind,
    SCENE_ENVIRONMENTS(SCENE_ENVIRONMENT_ENUMERATOR)
#undef SCENE_ENVIRONMENT_ENUMERATOR
};

struct Environment {
    EnvironmentKind kind = EnvironmentKind::Sky;
    glm::vec3 color{0.0f};  // Constant only
};

struct EnvironmentDescription {
    EnvironmentKind kind;
    int code;                // its place in the list; the shaders' ENVIRONMENT_<IDENTIFIER>
    const char* identifier;  // the enumerator's name
    const char* keyword;
    const char* alias;       // "" for none
    bool hasColour;          // a colour 'r g b' follows the word (which may then be left out)
};

// Every environment kind, in code order.
const std::vector<EnvironmentDescription>& environmentDescriptions();
const EnvironmentDescription& describe(EnvironmentKind kind);
// The kind a scene file's word (its keyword or its alias) names, or nullptr.
const EnvironmentDescription* findEnvironmentKind(const std::string& word);
// The shaders' name for an environment kind's code: ENVIRONMENT_ and the identifier in capitals.
std::string codeName(const EnvironmentDescription& description);

}  // namespace scene
