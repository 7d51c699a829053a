#pragma once
// A row of the option table bound to the field it sets: from its description and the field's
// type come the parse of its command-line value, the word it is recorded as in files, and
// the value the shader is given (settings/OptionValues.h says how, per type).
#include "settings/OptionDescription.h"
#include "settings/OptionValues.h"

#include <functional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace settings {

template <typename Owner>
struct BoundOption {
    std::string field;  // the member's name ("hitTolerance", "adaptiveSampling.tileSize")
    OptionDescription description;

    // Sets the field from the command line: `value` is the text given with the flag (empty
    // for a switch). Throws UsageError for a value the option does not accept.
    std::function<void(Owner&, const std::string& value)> apply;
    // The field as one word ("0.25", "on", "sobol"), and back: for the files' metadata and
    // for --help's default. Null where the field's type has no word.
    std::function<std::string(const Owner&)> format;
    std::function<bool(Owner&, const std::string& word)> read;
    // The value the shader is given (where description.uniformModule is set).
    std::function<UniformValue(const Owner&)> uniform;
    const char* glslType = nullptr;
    // A choice's accepted words and, for --help, what each means.
    std::vector<std::string> choiceNames;
    std::string choiceMeanings;
    // "#define SAMPLER_SOBOL 1" lines, where the shader sees the choice (Choices.h).
    std::string choiceDefines;

    bool isOption() const { return !description.flag.empty(); }
    bool takesValue() const { return !description.valueName.empty(); }
    bool isRecorded() const { return !description.metadataKey.empty(); }
    bool isUniform() const { return !description.uniformModule.empty(); }
    // "--hit-tolerance", or what sets it where no option does.
    const std::string& setBy() const { return isOption() ? description.flag : description.setBy; }
};

// Binds `description` to the field `access(owner)` returns (a generic lambda, so that it
// serves const and non-const owners alike). Throws std::logic_error for a row that asks of
// its field what the field's type cannot give (a switch without a value to set, metadata or
// a uniform of a type without a word or a GLSL type): the tables are built once, at start.
template <typename Owner, typename Access>
BoundOption<Owner> bindOption(std::string field, Access access, OptionDescription description)
{
    using T = std::remove_cv_t<std::remove_reference_t<decltype(access(std::declval<Owner&>()))>>;
    auto wrong = [&](const std::string& why) {
        return std::logic_error("option table row " + field + ": " + why);
    };
    BoundOption<Owner> row;
    row.field = field;
    if (description.isSwitch()) {
        if (!description.switchValue.has_value())
            throw wrong("a switch needs .sets(value)");
        T value{};
        try {
            value = std::any_cast<T>(description.switchValue);
        } catch (const std::bad_any_cast&) {
            throw wrong(".sets(value) must give a value of the field's type");
        }
        row.apply = [access, value](Owner& owner, const std::string&) { access(owner) = value; };
    } else if (description.reader) {
        row.apply = [access, reader = description.reader, field](Owner& owner,
                                                                 const std::string& text) {
            try {
                access(owner) = std::any_cast<T>(reader(text));
            } catch (const std::bad_any_cast&) {
                throw std::logic_error("option table row " + field +
                                       ": .readBy must give a value of the field's type");
            }
        };
    } else if (!description.flag.empty()) {
        if constexpr (isParseable<T>())
            row.apply = [access, range = description.range,
                         flag = description.flag](Owner& owner, const std::string& text) {
                access(owner) = parseValue<T>(text, range, flag);
            };
        else
            throw wrong("no value can be read for its type: make it a switch (.sets)");
    }
    if constexpr (isWordType<T>()) {
        row.format = [access](const Owner& owner) { return formatValue<T>(access(owner)); };
        row.read = [access](Owner& owner, const std::string& word) {
            return readValue<T>(word, access(owner));
        };
    } else if (!description.metadataKey.empty()) {
        throw wrong("its type has no word to record in a file");
    }
    if (!description.uniformModule.empty()) {
        if constexpr (isUniformType<T>()) {
            row.uniform = [access](const Owner& owner) { return uniformValue<T>(access(owner)); };
            row.glslType = std::visit(
                [](const auto& value) { return glslTypeOf<std::decay_t<decltype(value)>>(); },
                uniformValue<T>(T{}));
        } else {
            throw wrong("the shader cannot read its type");
        }
    }
    if constexpr (IsChoice<T>::value) {
        for (const auto& choice : Choices<T>::values) {
            row.choiceNames.push_back(choice.name);
            if (*choice.meaning != '\0')
                row.choiceMeanings += (row.choiceMeanings.empty() ? "" : "; ") +
                                      std::string(choice.name) + ": " + choice.meaning;
            if (Choices<T>::glslPrefix != nullptr)
                row.choiceDefines += "#define " + choiceMacro(Choices<T>::glslPrefix, choice.name) +
                                     " " + std::to_string(choiceCode(choice.value)) + "\n";
        }
    }
    row.description = std::move(description);
    return row;
}

}  // namespace settings
