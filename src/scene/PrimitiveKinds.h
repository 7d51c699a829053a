#pragma once
// The primitive kinds of scene/Primitives.h as one table, for what walks them all: the
// parser, the generated #defines and distance calls, the interpreter's switch, the tests.
#include "scene/Scene.h"

#include <string>
#include <type_traits>
#include <vector>

namespace scene {

struct PrimitiveKind {
    int code;  // its index in Geometry; the shaders' PRIMITIVE_<KEYWORD>
    const char* keyword;
    const char* distance;  // GLSL, over the parameter slots $0, $1, ...
    int parameterCount;    // vec4s; a union of terms has one per term
    bool unionOfTerms;     // the distance is the minimum of `distance` over every vec4
    Geometry (*read)(TokenCursor& in);

    // Exact intersection (scene/Primitives.h says what each member means); null `exact`:
    // rays always march it.
    const char* exact;
    const char* exactSetup;  // unions of terms only
    const char* exactTerm;
    const char* metExactlyGlsl;  // null: every shape of the kind is met exactly
    const char* exactLimit;      // the shapes it does not meet, for messages
    bool exactInWorld;           // met in world space (its parameters transformed)
    bool marchedOnRequest;
    // Whether this shape of the kind is met exactly; false for every shape of a kind
    // without an exact intersection.
    bool (*metExactly)(const Geometry& geometry);
    // The vec4s the exact call reads: in world space for a kind met there, else its own.
    std::vector<glm::vec4> (*exactParameters)(const Geometry& geometry,
                                              const std::optional<Transform>& transform);
};

template <typename T, typename List>
struct IsListed;
template <typename T, typename... Listed>
struct IsListed<T, TypeList<Listed...>> : std::bool_constant<(std::is_same_v<T, Listed> || ...)> {
};
template <typename T>
constexpr bool kIsPrimitive = IsListed<T, PrimitiveTypes>::value;

// Every kind, in code order.
const std::vector<PrimitiveKind>& primitiveKinds();
// The kind a scene file's word names, or nullptr.
const PrimitiveKind* findPrimitiveKind(const std::string& keyword);
// The kind of a geometry that is a primitive, or nullptr (a user SDF, a CSG node).
const PrimitiveKind* primitiveKindOf(const Geometry& geometry);

// The shaders' name for a kind's code: PRIMITIVE_ and the keyword in capitals.
std::string primitiveCodeName(const PrimitiveKind& kind);
// The code of a user SDF in the interpreter's program, after every primitive's.
int userSdfCode();

// A primitive's vec4s in uShapeParameters, and its bounding sphere in its own frame (ShapeBound{}
// for anything but a primitive).
std::vector<glm::vec4> primitiveParameters(const Geometry& geometry);
ShapeBound primitiveBound(const Geometry& geometry);

// A GLSL template (`distance`, `exact`, ...) with each $k written as slot(k).
template <typename Slot>
std::string overSlots(const char* glsl, Slot slot)
{
    std::string text;
    for (const char* c = glsl; *c != '\0'; ++c) {
        if (*c == '$' && c[1] >= '0' && c[1] <= '9')
            text += slot(*++c - '0');
        else
            text += *c;
    }
    return text;
}

template <typename Slot>
std::string distanceOverSlots(const PrimitiveKind& kind, Slot slot)
{
    return overSlots(kind.distance, slot);
}

}  // namespace scene
