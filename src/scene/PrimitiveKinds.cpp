#include "scene/PrimitiveKinds.h"

#include <cctype>
#include <tuple>
#include <utility>

namespace scene {

namespace {

template <typename P>
using ParametersOf = decltype(Primitive<P>::parameters(std::declval<const P&>()));

template <typename P>
constexpr bool kUnionOfTerms = std::is_same_v<ParametersOf<P>, std::vector<glm::vec4>>;

template <typename P>
constexpr int parameterCount()
{
    if constexpr (kUnionOfTerms<P>)
        return 1;
    else
        return static_cast<int>(std::tuple_size_v<ParametersOf<P>>);
}

// The optional members of a description (scene/Primitives.h), detected.
template <typename P, typename = void>
struct HasExact : std::false_type {
};
template <typename P>
struct HasExact<P, std::void_t<decltype(Primitive<P>::exact)>> : std::true_type {
};

template <typename P, typename = void>
struct HasExactTerm : std::false_type {
};
template <typename P>
struct HasExactTerm<P, std::void_t<decltype(Primitive<P>::exactTerm)>> : std::true_type {
};

template <typename P, typename = void>
struct IsMetInWorld : std::false_type {
};
template <typename P>
struct IsMetInWorld<P, std::void_t<decltype(Primitive<P>::parametersInWorld(
                           std::declval<const P&>(), std::declval<const Transform&>()))>>
    : std::true_type {
};

template <typename P, typename = void>
struct HasMetExactly : std::false_type {
};
template <typename P>
struct HasMetExactly<P, std::void_t<decltype(Primitive<P>::metExactly(std::declval<const P&>()))>>
    : std::true_type {
};

template <typename P, typename = void>
struct IsMarchedOnRequest : std::false_type {
};
template <typename P>
struct IsMarchedOnRequest<P, std::void_t<decltype(Primitive<P>::marchedOnRequest)>>
    : std::bool_constant<Primitive<P>::marchedOnRequest> {
};

template <typename P>
std::vector<glm::vec4> exactParametersOf(const Geometry& geometry,
                                         const std::optional<Transform>& transform)
{
    const P& shape = std::get<P>(geometry);
    if constexpr (IsMetInWorld<P>::value) {
        if (transform) {
            const auto values = Primitive<P>::parametersInWorld(shape, *transform);
            return {values.begin(), values.end()};
        }
    }
    const auto values = Primitive<P>::parameters(shape);
    return {values.begin(), values.end()};
}

template <typename P, std::size_t Code>
PrimitiveKind describe()
{
    static_assert(std::is_same_v<std::variant_alternative_t<Code, Geometry>, P>,
                  "a primitive's code is its index in Geometry");
    static_assert(HasExactTerm<P>::value == (HasExact<P>::value && kUnionOfTerms<P>),
                  "a union of terms met exactly has an exactTerm (and exactSetup); no other kind");
    static_assert(!HasExactTerm<P>::value || IsMetInWorld<P>::value,
                  "a union of terms is met in world space (its terms are statements, not a call)");
    using Description = Primitive<P>;
    PrimitiveKind kind{static_cast<int>(Code),
                       Description::keyword,
                       Description::distance,
                       parameterCount<P>(),
                       kUnionOfTerms<P>,
                       [](TokenCursor& in) -> Geometry { return Description::read(in); },
                       nullptr,
                       nullptr,
                       nullptr,
                       nullptr,
                       nullptr,
                       IsMetInWorld<P>::value,
                       IsMarchedOnRequest<P>::value,
                       [](const Geometry&) { return false; },
                       exactParametersOf<P>};
    if constexpr (HasExact<P>::value) {
        kind.exact = Description::exact;
        if constexpr (HasExactTerm<P>::value) {
            kind.exactSetup = Description::exactSetup;
            kind.exactTerm = Description::exactTerm;
        }
        if constexpr (HasMetExactly<P>::value) {
            kind.metExactlyGlsl = Description::metExactlyGlsl;
            kind.exactLimit = Description::exactLimit;
            kind.metExactly = [](const Geometry& geometry) {
                return Description::metExactly(std::get<P>(geometry));
            };
        } else {
            kind.metExactly = [](const Geometry&) { return true; };
        }
    }
    return kind;
}

template <typename... P, std::size_t... Code>
std::vector<PrimitiveKind> describeAll(TypeList<P...>, std::index_sequence<Code...>)
{
    return {describe<P, Code>()...};
}

template <typename... P>
std::vector<PrimitiveKind> describeAll(TypeList<P...> kinds)
{
    return describeAll(kinds, std::index_sequence_for<P...>{});
}

}  // namespace

const std::vector<PrimitiveKind>& primitiveKinds()
{
    static const std::vector<PrimitiveKind> kinds = describeAll(PrimitiveTypes{});
    return kinds;
}

const PrimitiveKind* findPrimitiveKind(const std::string& keyword)
{
    for (const PrimitiveKind& kind : primitiveKinds())
        if (keyword == kind.keyword)
            return &kind;
    return nullptr;
}

const PrimitiveKind* primitiveKindOf(const Geometry& geometry)
{
    const std::size_t index = geometry.index();
    return index < primitiveKinds().size() ? &primitiveKinds()[index] : nullptr;
}

std::string primitiveCodeName(const PrimitiveKind& kind)
{
    std::string name = "PRIMITIVE_";
    for (const char* c = kind.keyword; *c != '\0'; ++c)
        name += static_cast<char>(std::toupper(static_cast<unsigned char>(*c)));
    return name;
}

int userSdfCode()
{
    return static_cast<int>(primitiveKinds().size());
}

std::vector<glm::vec4> primitiveParameters(const Geometry& geometry)
{
    return std::visit(
        [](const auto& shape) -> std::vector<glm::vec4> {
            using P = std::decay_t<decltype(shape)>;
            if constexpr (kIsPrimitive<P>) {
                const auto values = Primitive<P>::parameters(shape);
                return {values.begin(), values.end()};
            } else {
                return {};
            }
        },
        geometry);
}

ShapeBound primitiveBound(const Geometry& geometry)
{
    return std::visit(
        [](const auto& shape) -> ShapeBound {
            using P = std::decay_t<decltype(shape)>;
            if constexpr (kIsPrimitive<P>)
                return Primitive<P>::bound(shape);
            else
                return {};
        },
        geometry);
}

}  // namespace scene
