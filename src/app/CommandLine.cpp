#include "app/CommandLine.h"

#include "io/ImageFormats.h"
#include "scene/SceneError.h"
#include "scene/SceneParser.h"
#include "scene/Spelling.h"
#include "settings/SettingsTable.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace app {

namespace {

using settings::BoundOption;

bool parseWhole(const std::string& text, long long& value)
{
    const char* last = text.data() + text.size();
    const auto [end, error] = std::from_chars(text.data(), last, value);
    return error == std::errc() && end == last;
}

bool parseDecimal(const std::string& text, double& value)
{
    const char* last = text.data() + text.size();
    const auto [end, error] = std::from_chars(text.data(), last, value);
    return error == std::errc() && end == last && std::isfinite(value);
}

int positiveInteger(const std::string& text, const std::string& what, long long maximum)
{
    long long value = 0;
    if (!parseWhole(text, value) || value < 1 || value > maximum)
        throw UsageError(what + " must be a whole number from 1 to " + std::to_string(maximum) +
                         ", not '" + text + "'");
    return static_cast<int>(value);
}

double positiveDecimal(const std::string& text, const std::string& what)
{
    double value = 0.0;
    if (!parseDecimal(text, value) || !(value > 0.0))
        throw UsageError(what + " must be a positive number, not '" + text + "'");
    return value;
}

// Image sides are checked against the GL's own limit once a context exists; this bound only
// keeps the numbers sane before that.
constexpr long long kLargestSide = 1 << 16;

// The --output paragraph of --help, from the table of formats.
std::string outputFormatsHelp()
{
    std::string text = "where to write; the extension names the format:";
    for (const io::ImageFormat& format : io::outputFormats()) {
        std::string names;
        for (const std::string& extension : format.extensions)
            names += (names.empty() ? "" : " ") + extension;
        names.resize(std::max<std::size_t>(names.size() + 2, 12), ' ');
        text += "\n" + names + format.holds;
    }
    return text;
}

// What was wrong in --camera's text, without the file and line a scene's error starts with:
// "read 'x', expected camera up vector".
std::string cameraErrorText(const scene::SceneError& error)
{
    return (error.token().empty() ? "reached its end"
                                  : "read '" + scene::shownToken(error.token()) + "'") +
           ", expected " + error.expected();
}

// A row of the command line's table: a heading of --help, an option of the program's own
// (a CommandLine member) or a render setting's (a member of CommandLine::settings).
struct Entry {
    std::string heading;
    std::optional<BoundOption<CommandLine>> option;
    const settings::SettingRow* setting = nullptr;

    static Entry section(std::string title) { return {std::move(title), std::nullopt, nullptr}; }
    static Entry of(BoundOption<CommandLine> row) { return {"", std::move(row), nullptr}; }
    static Entry of(const settings::SettingRow& row) { return {"", std::nullopt, &row}; }

    bool isHeading() const { return !option && setting == nullptr; }
    const settings::OptionDescription& description() const
    {
        return option ? option->description : setting->description;
    }
    bool isOption() const { return !isHeading() && !description().flag.empty(); }
    bool spelledAs(const std::string& word) const
    {
        const settings::OptionDescription& d = description();
        return word == d.flag ||
               std::find(d.aliases.begin(), d.aliases.end(), word) != d.aliases.end();
    }
    void apply(CommandLine& line, const std::string& value) const
    {
        if (option)
            option->apply(line, value);
        else
            setting->apply(line.settings, value);
    }
    // The default --help states, as a word ("0.25"); empty where it states none.
    std::string defaultWord() const
    {
        static const CommandLine defaults;
        if (option)
            return option->format ? option->format(defaults) : "";
        return setting->format ? setting->format(defaults.settings) : "";
    }
    const std::string& choiceMeanings() const
    {
        return option ? option->choiceMeanings : setting->choiceMeanings;
    }
};

// settings/Options.def's rows, in its order: the render's options.
const std::vector<Entry>& renderEntries()
{
    using namespace settings;
    static const std::vector<Entry> entries = {
#define SECTION(title) Entry::section(title),
#define OPTION(field, ...)                                                                         \
    Entry::of(bindOption<CommandLine>(                                                             \
        #field, [](auto& line) -> auto& { return line.field; }, __VA_ARGS__)),
#define SETTING(Type, field, defaultValue, ...) Entry::of(settingRow(#field)),
#include "settings/Options.def"
#undef SECTION
#undef OPTION
#undef SETTING
    };
    return entries;
}

const Entry& helpEntry()
{
    for (const Entry& entry : renderEntries())
        if (entry.isOption() && entry.spelledAs("--help"))
            return entry;
    throw std::logic_error("settings/Options.def has no --help");
}

// raytracer merge OUT.exr IN.exr... [--png FILE] [--stats-output FILE]
const std::vector<Entry>& mergeEntries()
{
    using namespace settings;
    static const std::vector<Entry> entries = {
        Entry::of(bindOption<CommandLine>(
            "merge.picture", [](auto& line) -> auto& { return line.merge.picture; },
            option("--png", "FILE", "the tone-mapped picture too"))),
        Entry::of(bindOption<CommandLine>(
            "merge.statisticsOutput",
            [](auto& line) -> auto& { return line.merge.statisticsOutput; },
            option("--stats-output", "FILE", "the merged statistics"))),
        helpEntry(),
    };
    return entries;
}

// raytracer info FILE
const std::vector<Entry>& infoEntries()
{
    static const std::vector<Entry> entries = {helpEntry()};
    return entries;
}

// " (did you mean --hit-tolerance?)" for the option nearest to `word`, within two edits.
std::string nearestOptionHint(const std::string& word, const std::vector<Entry>& entries)
{
    std::string nearest;
    std::size_t nearestDistance = scene::kMostEditsSuggested + 1;
    for (const Entry& entry : entries) {
        if (!entry.isOption())
            continue;
        std::vector<std::string> spellings = entry.description().aliases;
        spellings.push_back(entry.description().flag);
        for (const std::string& spelling : spellings) {
            const std::size_t distance = scene::editDistance(word, spelling);
            if (distance < nearestDistance) {
                nearest = entry.description().flag;
                nearestDistance = distance;
            }
        }
    }
    return nearest.empty() ? "" : " (did you mean " + nearest + "?)";
}

bool looksLikeOption(const std::string& argument)
{
    return argument.size() > 1 && argument[0] == '-' &&
           !(std::isdigit(static_cast<unsigned char>(argument[1])) || argument[1] == '.');
}

// Walks the arguments from `first` on: options (`--name value` or `--name=value`) are
// applied to `line` by their rows in `entries`, the rest go to `positional`. Each option
// once: a repeated one is more likely a mistake than a wish for the last.
void readArguments(int argc, const char* const argv[], int first, const std::vector<Entry>& entries,
                   CommandLine& line, std::vector<std::string>& positional)
{
    for (int i = first; i < argc; ++i) {
        const std::string argument = argv[i];
        if (!looksLikeOption(argument)) {
            positional.push_back(argument);
            continue;
        }
        const std::size_t equals =
            argument.rfind("--", 0) == 0 ? argument.find('=') : std::string::npos;
        const std::string word = argument.substr(0, equals);
        const auto entry = std::find_if(entries.begin(), entries.end(), [&](const Entry& e) {
            return e.isOption() && e.spelledAs(word);
        });
        if (entry == entries.end())
            throw UsageError("unknown option '" + word + "'" + nearestOptionHint(word, entries) +
                             " (see --help)");
        const settings::OptionDescription& description = entry->description();
        std::string value;
        if (description.isSwitch()) {
            if (equals != std::string::npos)
                throw UsageError(description.flag + " takes no value, not '" +
                                 argument.substr(equals + 1) + "'");
        } else if (equals != std::string::npos) {
            value = argument.substr(equals + 1);
        } else {
            if (i + 1 >= argc)
                throw UsageError(word + " needs a value");
            value = argv[++i];
        }
        if (!line.optionsGiven.insert(description.flag).second)
            throw UsageError(description.flag + " is given twice: give each option once");
        entry->apply(line, value);
    }
}

// raytracer WORD ...: the arguments after the word, read by `entries`.
CommandLine parseSubcommand(int argc, const char* const argv[], Action action,
                            const std::vector<Entry>& entries, std::vector<std::string>& positional)
{
    CommandLine line;
    line.action = action;
    readArguments(argc, argv, 2, entries, line, positional);
    return line;
}

// raytracer info FILE
CommandLine parseInfo(int argc, const char* const argv[])
{
    std::vector<std::string> positional;
    CommandLine line = parseSubcommand(argc, argv, Action::Info, infoEntries(), positional);
    if (line.action == Action::Help)
        return line;
    if (positional.size() != 1)
        throw UsageError("info takes one file: raytracer info FILE");
    line.infoFile = positional[0];
    return line;
}

// raytracer denoise IN.exr OUT
CommandLine parseDenoise(int argc, const char* const argv[])
{
    std::vector<std::string> positional;
    CommandLine line = parseSubcommand(argc, argv, Action::Denoise, infoEntries(), positional);
    if (line.action == Action::Help)
        return line;
    if (positional.size() != 2)
        throw UsageError("denoise takes an input and an output: raytracer denoise IN.exr OUT");
    line.denoising.input = positional[0];
    line.denoising.output = positional[1];
    if (io::lowerCaseExtension(line.denoising.input) != ".exr")
        throw UsageError("denoise reads an .exr this program wrote with feature buffers, not '" +
                         line.denoising.input.string() + "'");
    return line;
}

// raytracer merge OUT.exr IN.exr... [--png FILE] [--stats-output FILE]
CommandLine parseMerge(int argc, const char* const argv[])
{
    std::vector<std::string> positional;
    CommandLine line = parseSubcommand(argc, argv, Action::Merge, mergeEntries(), positional);
    if (line.action == Action::Help)
        return line;
    if (positional.size() < 2)
        throw UsageError("merge needs an output and at least one input: raytracer merge "
                         "OUT.exr IN.exr...");
    line.merge.output = positional[0];
    line.merge.inputs.assign(positional.begin() + 1, positional.end());
    if (io::lowerCaseExtension(line.merge.output) != ".exr")
        throw UsageError("merge writes an OpenEXR file (it holds what a later merge needs): '" +
                         line.merge.output.string() + "' must end in .exr");
    if (line.merge.picture && io::lowerCaseExtension(*line.merge.picture) != ".png")
        throw UsageError("--png names a .png file, not '" + line.merge.picture->string() + "'");
    return line;
}

// SCENE [WIDTH HEIGHT] [SECONDS]
void readPositional(const std::vector<std::string>& positional, CommandLine& line)
{
    if (positional.empty())
        throw UsageError("no scene file given (see --help)");
    line.scene = positional[0];
    if (positional.size() == 2)
        throw UsageError("give both WIDTH and HEIGHT, not only '" + positional[1] + "'");
    if (positional.size() >= 3) {
        line.width = positiveInteger(positional[1], "WIDTH", kLargestSide);
        line.height = positiveInteger(positional[2], "HEIGHT", kLargestSide);
        line.sizeGiven = true;
    }
    if (positional.size() >= 4)
        line.seconds = positiveDecimal(positional[3], "SECONDS");
    if (positional.size() > 4)
        throw UsageError("unexpected argument '" + positional[4] + "' (see --help)");
}

}  // namespace

std::filesystem::path CommandLine::outputPath() const
{
    if (output)
        return *output;
    if (resume)
        return *resume;
    return scene.stem().string() + ".ppm";
}

CommandLine parseCommandLine(int argc, const char* const argv[])
{
    // A scene file called "info", "merge" or "denoise" is ./info, ./merge or ./denoise.
    if (argc > 1 && std::string(argv[1]) == "info")
        return parseInfo(argc, argv);
    if (argc > 1 && std::string(argv[1]) == "merge")
        return parseMerge(argc, argv);
    if (argc > 1 && std::string(argv[1]) == "denoise")
        return parseDenoise(argc, argv);

    CommandLine line;
    std::vector<std::string> positional;
    readArguments(argc, argv, 1, renderEntries(), line, positional);
    if (line.action == Action::Help || line.action == Action::Version)
        return line;
    if (line.glDevice) {
        if (line.gl == platform::ContextKind::OsMesa || line.gl == platform::ContextKind::Window)
            throw UsageError(std::string("--gl-device picks a GPU through EGL: it does not go "
                                         "with --gl ") +
                             platform::contextKindName(line.gl));
        line.gl = platform::ContextKind::Gpu;
    }
    if (line.gl == platform::ContextKind::Window && line.headless)
        throw UsageError("--headless and --gl window contradict each other: give one");
    if (line.gl == platform::ContextKind::Window && line.resume)
        throw UsageError("--resume renders headless: it does not go with --gl window");
    readPositional(positional, line);
    if (line.crop) {
        if (line.crop->x1 > line.width || line.crop->y1 > line.height)
            throw UsageError("--crop " + film::formatCrop(*line.crop) + " reaches beyond the " +
                             std::to_string(line.width) + "x" + std::to_string(line.height) +
                             " frame: X1 and Y1 are at most its width and height");
        if (line.targetError)
            throw UsageError("--crop does not go with --target-error (whose error is the "
                             "whole frame's): give --spp N or SECONDS");
        if (line.resume)
            throw UsageError("--crop does not go with --resume: render the crop anew");
        if (line.action == Action::Render && !line.isBatch())
            throw UsageError("--crop renders headless: give SECONDS or --spp");
        if (line.gl == platform::ContextKind::Window)
            throw UsageError("--crop renders headless: it does not go with --gl window");
    }
    if (line.resume && line.action == Action::Render && !line.isBatch())
        throw UsageError("--resume goes on to an end: give --spp N (samples per pixel in all), "
                         "--target-error E or SECONDS (more)");
    if (line.targetError)
        line.adaptiveSampling.targetError = *line.targetError;
    if (line.samplesPerPixel)
        line.adaptiveSampling.sampleLimit = *line.samplesPerPixel;
    return line;
}

namespace {

constexpr std::size_t kHelpWidth = 92;
constexpr std::size_t kHelpColumn = 24;

// `text` wrapped at kHelpWidth, every line after the first indented to kHelpColumn; a
// newline in `text` starts a line there too, and a line that fits is kept as it is written
// (a list's alignment).
std::string wrapHelp(const std::string& text)
{
    const std::string indent(kHelpColumn, ' ');
    std::string result;
    std::size_t start = 0;
    while (true) {
        const std::size_t newline = std::min(text.find('\n', start), text.size());
        const std::string paragraph = text.substr(start, newline - start);
        if (kHelpColumn + paragraph.size() <= kHelpWidth) {
            result += paragraph;
        } else {
            std::istringstream words(paragraph);
            std::size_t column = kHelpColumn;
            bool first = true;
            for (std::string word; words >> word; first = false) {
                if (!first && column + 1 + word.size() > kHelpWidth) {
                    result += "\n" + indent;
                    column = kHelpColumn;
                } else if (!first) {
                    result += ' ';
                    ++column;
                }
                result += word;
                column += word.size();
            }
        }
        if (newline == text.size())
            return result;
        result += "\n" + indent;
        start = newline + 1;
    }
}

// The help's "{default}" replaced by the default, or "(default ...)" appended.
std::string withDefault(std::string help, const std::string& value)
{
    const std::string placeholder = "{default}";
    const std::size_t at = help.find(placeholder);
    if (at != std::string::npos)
        return help.replace(at, placeholder.size(), value);
    return help + " (" + value + ")";
}

std::string helpLine(const Entry& entry)
{
    const settings::OptionDescription& d = entry.description();
    std::string names;
    for (const std::string& alias : d.aliases)
        names += alias + ", ";
    names = "  " + names + d.flag + (d.valueName.empty() ? "" : " " + d.valueName);
    if (names.size() + 1 > kHelpColumn)
        names += "\n" + std::string(kHelpColumn, ' ');
    else
        names.resize(kHelpColumn, ' ');
    std::string text = d.help;
    if (d.showDefault) {
        if (!d.defaultText.empty())
            text = withDefault(text, "default: " + d.defaultText);
        else if (const std::string word = entry.defaultWord(); !word.empty())
            text = withDefault(text, "default " + word);
    }
    if (!entry.choiceMeanings().empty())
        text += ". " + entry.choiceMeanings();
    return names + wrapHelp(text) + "\n";
}

// The options' part of --help, from the table.
std::string optionsHelp()
{
    std::string text;
    for (const Entry& entry : renderEntries()) {
        if (entry.isHeading())
            text += "\n" + (entry.heading.empty() ? "" : entry.heading + ":\n");
        else if (entry.isOption())
            text += helpLine(entry);
    }
    return text;
}

}  // namespace

std::string usageText()
{
    return R"(usage: raytracer SCENE [WIDTH HEIGHT] [SECONDS] [options]
       raytracer SCENE [WIDTH HEIGHT] [SECONDS] --resume FILE.exr [--spp N] [options]
       raytracer merge OUT.exr IN.exr... [--png FILE.png] [--stats-output FILE]
       raytracer info FILE
       raytracer denoise IN.exr OUT

Renders SCENE (a .in scene file) by path tracing on the GPU, WIDTH x HEIGHT pixels
(default 640 480). Without SECONDS or --spp a window shows the image converging until it
is closed (Escape closes it; its panel, Tab, lists the keys and mouse actions). With
SECONDS the render runs that long, then writes the tone-mapped image as SCENE-NAME.ppm in
the current folder (or --output). Without a display, or with --headless, rendering opens no
window: it goes through EGL on a GPU, else EGL on Mesa's software device, else OSMesa (--gl
says which; every summary line names the OpenGL renderer). Each option may be given once,
as --name VALUE or --name=VALUE.

EXR and PNG files describe themselves in their headers (samples, seeds, settings, the
scene's SHA-256, the program); an EXR also holds each pixel's sample count and second
moments, so that renders can be merged and resumed (docs/SCALE_OUT.md):
  merge                 combines renders of one scene, size and settings into OUT.exr, as
                        one render of all their samples would; refuses (one line, nothing
                        written) inputs that differ or share samples of one seed.
                        --png FILE: the tone-mapped picture too; --stats-output FILE: the
                        merged statistics
  info                  prints what a file says of itself
  denoise               writes IN.exr (a render or merge with feature buffers) denoised by
                        Open Image Denoise into OUT (docs/DENOISING.md)

Exit status: 0 done; 1 the scene, a file or the OpenGL failed (or, with --strict, a warning);
2 the command line cannot be run; 3 a render to --target-error ended at SECONDS or --spp
before reaching it (its image is written); 130 interrupted (the image so far is written).
)" + optionsHelp();
}

}  // namespace app
