#pragma once
// How a value of each type a setting may have is read from the command line, written to and
// read from a file's metadata, and handed to the shader: the one place that knows, per type,
// what bindOption (settings/OptionTable.h) does with a field.
#include "settings/Choices.h"
#include "settings/OptionDescription.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>
#include <variant>

namespace settings {

// A value the shader is given as a uniform (not an array): a setting's, or one of the scene's
// (render/SceneUniforms.h).
using UniformValue =
    std::variant<int, unsigned int, float, bool, glm::vec2, glm::vec3, glm::uvec2, glm::ivec4>;

// The GLSL type of a uniform holding a T.
template <typename T>
constexpr const char* glslTypeOf()
{
    if constexpr (std::is_same_v<T, float>)
        return "float";
    else if constexpr (std::is_same_v<T, int>)
        return "int";
    else if constexpr (std::is_same_v<T, unsigned int>)
        return "uint";
    else if constexpr (std::is_same_v<T, bool>)
        return "bool";
    else if constexpr (std::is_same_v<T, glm::vec2>)
        return "vec2";
    else if constexpr (std::is_same_v<T, glm::vec3>)
        return "vec3";
    else if constexpr (std::is_same_v<T, glm::uvec2>)
        return "uvec2";
    else if constexpr (std::is_same_v<T, glm::ivec4>)
        return "ivec4";
    else
        static_assert(sizeof(T) == 0, "no uniform of this type");
}

// The shortest decimal that reads back as the same float (nine significant digits always
// do): 1.2, not 1.20000005.
std::string shortestFloatText(float value);
// The shortest decimal that reads back as the same double (up to 17 digits): 0.15, not
// 0.14999999999999999.
std::string shortestDoubleText(double value);

// Strict readers: the whole text, a finite value.
bool readFloat(const std::string& text, float& value);
bool readDouble(const std::string& text, double& value);
bool readInteger(const std::string& text, long long& value);

// A number from the command line, checked against `range`; throws UsageError naming `flag`.
long long parseWholeNumber(const std::string& text, const Range& range, const std::string& flag);
double parseDecimalNumber(const std::string& text, const Range& range, const std::string& flag);

template <typename T, typename = void>
struct IsChoice : std::false_type {
};
template <typename T>
struct IsChoice<T, std::void_t<decltype(Choices<T>::values)>> : std::true_type {
};

template <typename T>
struct IsOptional : std::false_type {
};
template <typename T>
struct IsOptional<std::optional<T>> : std::true_type {
};

// "'sobol' or 'independent'"
template <typename Enum>
std::string choiceList()
{
    std::string text;
    const auto& values = Choices<Enum>::values;
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (i > 0)
            text += i + 1 == values.size() ? " or " : ", ";
        text += std::string("'") + values[i].name + "'";
    }
    return text;
}

// The #define a choice's code reaches GLSL as: ("SAMPLER_", "sobol") -> "SAMPLER_SOBOL".
std::string choiceMacro(const std::string& prefix, const std::string& name);

// Whether the command line can give a field of type T a value (other types are set by
// switches only).
template <typename T>
constexpr bool isParseable()
{
    if constexpr (IsOptional<T>::value)
        return isParseable<typename T::value_type>();
    else
        return std::is_same_v<T, std::filesystem::path> || std::is_same_v<T, std::string> ||
               IsChoice<T>::value || (std::is_arithmetic_v<T> && !std::is_same_v<T, bool>);
}

// The value `text` gives a field of type T, as the command line reads it.
template <typename T>
T parseValue(const std::string& text, const Range& range, const std::string& flag)
{
    if constexpr (IsOptional<T>::value) {
        return parseValue<typename T::value_type>(text, range, flag);
    } else if constexpr (std::is_same_v<T, std::filesystem::path> ||
                         std::is_same_v<T, std::string>) {
        return T(text);
    } else if constexpr (IsChoice<T>::value) {
        for (const auto& choice : Choices<T>::values)
            if (text == choice.name)
                return choice.value;
        throw UsageError(flag + " must be " + choiceList<T>() + ", not '" + text + "'");
    } else {
        static_assert(std::is_arithmetic_v<T> && !std::is_same_v<T, bool>,
                      "a setting of this type is a switch (.sets) or needs a reader here");
        if constexpr (std::is_integral_v<T>)
            return static_cast<T>(parseWholeNumber(text, range, flag));
        else
            return static_cast<T>(parseDecimalNumber(text, range, flag));
    }
}

// Whether format and read below know T (what a file's metadata and --help's default need).
template <typename T>
constexpr bool isWordType()
{
    return std::is_same_v<T, float> || std::is_same_v<T, double> || std::is_same_v<T, int> ||
           std::is_same_v<T, std::uint64_t> || std::is_same_v<T, bool> || IsChoice<T>::value;
}

// The value as one word: "0.25", "512", "on", "sobol".
template <typename T>
std::string formatValue(const T& value)
{
    if constexpr (std::is_same_v<T, float>)
        return shortestFloatText(value);
    else if constexpr (std::is_same_v<T, double>)
        return shortestDoubleText(value);
    else if constexpr (std::is_same_v<T, bool>)
        return value ? "on" : "off";
    else if constexpr (IsChoice<T>::value)
        return Choices<T>::values[static_cast<std::size_t>(choiceCode(value))].name;
    else
        return std::to_string(value);
}

// formatValue's inverse; false when `text` is no value of T.
template <typename T>
bool readValue(const std::string& text, T& value)
{
    if constexpr (std::is_same_v<T, float>) {
        return readFloat(text, value);
    } else if constexpr (std::is_same_v<T, double>) {
        return readDouble(text, value);
    } else if constexpr (std::is_same_v<T, bool>) {
        if (text != "on" && text != "off")
            return false;
        value = text == "on";
        return true;
    } else if constexpr (IsChoice<T>::value) {
        for (const auto& choice : Choices<T>::values)
            if (text == choice.name) {
                value = choice.value;
                return true;
            }
        return false;
    } else {
        long long whole = 0;
        if (!readInteger(text, whole) ||
            whole < static_cast<long long>(std::numeric_limits<T>::min()))
            return false;
        if (static_cast<unsigned long long>(whole) > std::numeric_limits<T>::max())
            return false;
        value = static_cast<T>(whole);
        return true;
    }
}

// Whether the shader can read a T, and as what.
template <typename T>
constexpr bool isUniformType()
{
    return std::is_same_v<T, float> || std::is_same_v<T, int> || std::is_same_v<T, bool> ||
           std::is_same_v<T, std::uint64_t> || IsChoice<T>::value;
}

// A setting of type T is given to the shader as what this returns: a 64-bit number as a
// uvec2, low word first (GLSL 3.30 has no 64-bit integers), a choice as its code.
template <typename T>
UniformValue uniformValue(const T& value)
{
    if constexpr (std::is_same_v<T, std::uint64_t>)
        return glm::uvec2(static_cast<std::uint32_t>(value),
                          static_cast<std::uint32_t>(value >> 32));
    else if constexpr (IsChoice<T>::value)
        return choiceCode(value);
    else
        return value;
}

}  // namespace settings
