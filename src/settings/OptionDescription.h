#pragma once
// What a row of the option table (settings/Options.def) says of its setting beyond the
// field: the command-line flag and its help, the values it accepts, the key it is recorded
// under in a file's metadata, and the shader module that reads it as a uniform. Rows are
// written with the builders below:
//
//     option("--max-steps", "N", "sphere-tracing step limit per ray")
//         .check(wholeFrom(1, 1 << 20))
//         .metadata("maxSteps", "sphere-tracing step limit")
//         .uniform("sphere_tracing.glsl")
#include <any>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace settings {

// A command line that cannot be run; what() is the message for the user.
class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The numbers an option accepts.
struct Range {
    double low = -std::numeric_limits<double>::infinity();
    bool lowIncluded = true;
    double high = std::numeric_limits<double>::infinity();
    bool highIncluded = true;
    bool whole = false;  // whole numbers only

    Range below(double limit) const;
    Range atMost(double limit) const;
    bool contains(double value) const;
    // "a whole number from 1 to 1024", "a positive number", "a number above 0 and at most 1"
    std::string describe() const;
};

Range positive();           // above 0
Range atLeast(double low);  // low or more
Range above(double low);    // more than low
Range wholeFrom(long long low, long long high);
Range wholeAtLeast(long long low);

class OptionDescription {
public:
    OptionDescription& check(Range accepted);
    // Another spelling of the flag ("-o" for "--output").
    OptionDescription& alias(std::string spelling);
    // The option takes no value and sets the field to `value`.
    template <typename Value>
    OptionDescription& sets(Value value)
    {
        switchValue = std::move(value);
        return *this;
    }
    // The command line's value is read by `reader` (the text to a value of the field's type,
    // in a std::any; it throws UsageError for text it does not accept) instead of by the
    // field's type: for a type settings/OptionValues.h cannot read (one of another layer's).
    OptionDescription& readBy(std::function<std::any(const std::string& text)> reader);
    // --help states this instead of the field's default (a default the program chooses).
    OptionDescription& defaultShown(std::string text);
    OptionDescription& noDefaultShown();
    // Recorded in the metadata of the files written (film/RenderMetadata.h): a setting that
    // changes the image, so that renders that differ in it are never merged or resumed.
    OptionDescription& metadata(std::string key, std::string label);
    // The shader reads it as a uniform (u + the field's name, capitalised), declared with
    // its per-pixel copy in the generated preamble when `module` is part of the shader;
    // inside `#if guard` where a guard is given (a feature's define, HAS_MICROFACET), so that
    // a shader without the feature declares none of it.
    OptionDescription& uniform(std::string module, std::string guard = "");

    // A command-line option that takes no value.
    bool isSwitch() const { return !flag.empty() && valueName.empty(); }

    std::string flag;  // empty: no command-line option
    std::vector<std::string> aliases;
    std::string valueName;  // "N"; empty: a switch (sets switchValue)
    std::string help;       // "{default}" marks where the default goes
    Range range;            // for numbers
    std::any switchValue;
    std::function<std::any(const std::string&)> reader;  // null: by the field's type
    std::string defaultText;  // "" : the field's default; see showDefault
    bool showDefault = true;
    std::string metadataKey;  // empty: not recorded
    std::string metadataLabel;
    std::string setBy;          // what sets a setting that has no flag
    std::string uniformModule;  // empty: no uniform
    std::string uniformGuard;   // empty: declared wherever the module is
};

// An option that takes a value, named `valueName` in --help.
OptionDescription option(std::string flag, std::string valueName, std::string help);
// An option without a value: give it .sets(value).
OptionDescription switchOption(std::string flag, std::string help);
// A setting no command-line option sets (`setBy` says what does, for messages).
OptionDescription notAnOption(std::string setBy);

}  // namespace settings
