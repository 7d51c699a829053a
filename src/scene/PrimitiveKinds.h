#pragma once
// The primitive kinds of scene/Primitives.h as one table, for what walks them all: the
// parser, the generated #defines and distance calls, the interpreter's switch, the tests.
#include "scene/Scene.h"

#include <string>
#include <type_traits>
#include <vector>

namespace scene {

struct PrimitiveKind {
    int code;               // its index in Geometry; the shaders' PRIMITIVE_<KEYWORD>
    const char* keyword;
    const char* distance;   // GLSL, over the parameter slots $0, $1, ...
    int parameterCount;     // vec4s; a union of terms has one per term
    bool unionOfTerms;      // the distance is the minimum of `distance` over every vec4
    Geometry (*read)(TokenCursor& in);
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

// `distance` with each $k written as slot(k).
template <typename Slot>
std::string distanceOverSlots(const PrimitiveKind& kind, Slot slot)
{
    std::string text;
    for (const char* c = kind.distance; *c != '\0'; ++c) {
        if (*c == '$' && c[1] >= '0' && c[1] <= '9')
            text += slot(*++c - '0');
        else
            text += *c;
    }
    return text;
}

}  // namespace scene
