#include "app/CommandLine.h"

#include "io/ImageFormats.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <set>
#include <vector>

namespace app {

namespace {

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

int nonNegativeInteger(const std::string& text, const std::string& what, long long maximum)
{
    long long value = 0;
    if (!parseWhole(text, value) || value < 0 || value > maximum)
        throw UsageError(what + " must be a whole number from 0 to " + std::to_string(maximum) +
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

}  // namespace

std::filesystem::path CommandLine::outputPath() const
{
    if (output)
        return *output;
    if (resume)
        return *resume;
    return scene.stem().string() + ".ppm";
}

namespace {

bool looksLikeOption(const std::string& argument)
{
    return argument.size() > 1 && argument[0] == '-' &&
           !(std::isdigit(static_cast<unsigned char>(argument[1])) || argument[1] == '.');
}

// Walks the arguments from `first` on: options (with their values) go to `option`, which
// returns false for one it does not know, the rest to `positional`. Each option once: a
// repeated one is more likely a mistake than a wish for the last.
template <typename OptionHandler>
void readArguments(int argc, const char* const argv[], int first,
                   std::vector<std::string>& positional, OptionHandler option)
{
    std::set<std::string> optionsGiven;
    for (int i = first; i < argc; ++i) {
        const std::string argument = argv[i];
        auto value = [&](const std::string& name) -> std::string {
            if (i + 1 >= argc)
                throw UsageError(name + " needs a value");
            return argv[++i];
        };
        if (!looksLikeOption(argument)) {
            positional.push_back(argument);
            continue;
        }
        if (!option(argument, value))
            throw UsageError("unknown option '" + argument + "' (see --help)");
        const std::string name =
            argument == "-o" ? "--output" : argument == "-h" ? "--help" : argument;
        if (!optionsGiven.insert(name).second)
            throw UsageError(name + " is given twice: give each option once");
    }
}

// raytracer info FILE
CommandLine parseInfo(int argc, const char* const argv[])
{
    CommandLine line;
    line.action = Action::Info;
    std::vector<std::string> positional;
    readArguments(argc, argv, 2, positional, [&](const std::string& argument, auto&) {
        if (argument != "--help" && argument != "-h")
            return false;
        line.action = Action::Help;
        return true;
    });
    if (line.action == Action::Help)
        return line;
    if (positional.size() != 1)
        throw UsageError("info takes one file: raytracer info FILE");
    line.infoFile = positional[0];
    return line;
}

// raytracer merge OUT.exr IN.exr... [--png FILE] [--stats-output FILE]
CommandLine parseMerge(int argc, const char* const argv[])
{
    CommandLine line;
    line.action = Action::Merge;
    std::vector<std::string> positional;
    readArguments(argc, argv, 2, positional, [&](const std::string& argument, auto& value) {
        if (argument == "--help" || argument == "-h")
            line.action = Action::Help;
        else if (argument == "--png")
            line.merge.picture = value(argument);
        else if (argument == "--stats-output")
            line.merge.statisticsOutput = value(argument);
        else
            return false;
        return true;
    });
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

}  // namespace

CommandLine parseCommandLine(int argc, const char* const argv[])
{
    // A scene file called "info" or "merge" is ./info or ./merge.
    if (argc > 1 && std::string(argv[1]) == "info")
        return parseInfo(argc, argv);
    if (argc > 1 && std::string(argv[1]) == "merge")
        return parseMerge(argc, argv);

    CommandLine line;
    std::vector<std::string> positional;
    readArguments(argc, argv, 1, positional, [&](const std::string& argument, auto& value) {
        if (argument == "--help" || argument == "-h") {
            line.action = Action::Help;
        } else if (argument == "--version") {
            line.action = Action::Version;
        } else if (argument == "--features") {
            line.action = Action::PrintFeatures;
        } else if (argument == "--print-shader") {
            line.action = Action::PrintShader;
        } else if (argument == "--spp") {
            line.samplesPerPixel = positiveInteger(value(argument), "--spp", 1 << 24);
        } else if (argument == "--target-error") {
            const double error = positiveDecimal(value(argument), "--target-error");
            if (error > 1.0)
                throw UsageError("--target-error is a relative error, above 0 and at most 1 "
                                 "(0.01 is 1 %)");
            line.targetError = error;
        } else if (argument == "--min-spp") {
            line.adaptiveSampling.minimumSamples =
                positiveInteger(value(argument), "--min-spp", 1 << 24);
        } else if (argument == "--adaptive-tile") {
            line.adaptiveSampling.tileSize = positiveInteger(value(argument), "--adaptive-tile", 256);
        } else if (argument == "--uniform-sampling") {
            line.uniformSampling = true;
        } else if (argument == "--output" || argument == "-o") {
            line.output = value(argument);
        } else if (argument == "--stats-output") {
            line.statisticsOutput = value(argument);
        } else if (argument == "--headless") {
            line.headless = true;
        } else if (argument == "--quiet") {
            line.quiet = true;
        } else if (argument == "--seed") {
            long long seed = 0;
            const std::string text = value(argument);
            if (!parseWhole(text, seed) || seed < 0)
                throw UsageError("--seed must be a whole number of 0 or more, not '" + text + "'");
            line.settings.seed = static_cast<std::uint64_t>(seed);
            line.seedGiven = true;
        } else if (argument == "--no-specialize") {
            line.settings.variant = settings::ShaderVariant::General;
        } else if (argument == "--hit-tolerance") {
            line.settings.hitTolerance =
                static_cast<float>(positiveDecimal(value(argument), "--hit-tolerance"));
        } else if (argument == "--max-steps") {
            line.settings.maxMarchSteps = positiveInteger(value(argument), "--max-steps", 1 << 20);
        } else if (argument == "--over-relaxation") {
            const double omega = positiveDecimal(value(argument), "--over-relaxation");
            if (omega < 1.0 || omega >= 2.0)
                throw UsageError("--over-relaxation must be at least 1 and below 2");
            line.settings.overRelaxation = static_cast<float>(omega);
        } else if (argument == "--step-scale") {
            const double scale = positiveDecimal(value(argument), "--step-scale");
            if (scale > 1.0)
                throw UsageError("--step-scale must be above 0 and at most 1");
            line.settings.stepScale = static_cast<float>(scale);
        } else if (argument == "--samples-per-frame") {
            line.settings.samplesPerFrame =
                positiveInteger(value(argument), "--samples-per-frame", 1 << 16);
            line.samplesPerFrameGiven = true;
        } else if (argument == "--band-seconds") {
            double seconds = 0.0;
            const std::string text = value(argument);
            if (!parseDecimal(text, seconds) || seconds < 0.0)
                throw UsageError("--band-seconds must be a number of 0 or more, not '" + text +
                                 "'");
            line.settings.secondsPerBand = seconds;
        } else if (argument == "--max-bounces") {
            line.settings.maxBounces = nonNegativeInteger(value(argument), "--max-bounces", 1024);
        } else if (argument == "--rr-depth") {
            line.settings.russianRouletteDepth =
                nonNegativeInteger(value(argument), "--rr-depth", 1024);
        } else if (argument == "--no-mis") {
            line.settings.multipleImportanceSampling = false;
        } else if (argument == "--exact-geometry") {
            line.settings.exactGeometry = true;
        } else if (argument == "--no-culling") {
            line.settings.rayCulling = false;
        } else if (argument == "--fresnel") {
            const std::string model = value(argument);
            if (model == "schlick")
                line.settings.dielectricFresnel = settings::FresnelModel::Schlick;
            else if (model == "exact")
                line.settings.dielectricFresnel = settings::FresnelModel::Exact;
            else
                throw UsageError("--fresnel must be 'schlick' or 'exact', not '" + model + "'");
        } else if (argument == "--sampler") {
            const std::string kind = value(argument);
            if (kind == "sobol")
                line.settings.sampler = settings::SamplerKind::Sobol;
            else if (kind == "independent")
                line.settings.sampler = settings::SamplerKind::Independent;
            else
                throw UsageError("--sampler must be 'sobol' or 'independent', not '" + kind +
                                 "'");
        } else if (argument == "--resume") {
            line.resume = value(argument);
        } else {
            return false;
        }
        return true;
    });

    if (line.action == Action::Help || line.action == Action::Version)
        return line;
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

// The --output paragraph of --help, from the table of formats.
std::string outputFormatsHelp()
{
    std::string text = "  --output FILE         where to write; the extension names the format:";
    for (const io::ImageFormat& format : io::outputFormats()) {
        std::string names;
        for (const std::string& extension : format.extensions)
            names += (names.empty() ? "" : " ") + extension;
        names.resize(std::max<std::size_t>(names.size() + 2, 12), ' ');
        text += "\n                        " + names + format.holds;
    }
    // No newline at the end: the text that follows it in usageText starts with one.
    return text;
}

}  // namespace

std::string usageText()
{
    return R"(usage: raytracer SCENE [WIDTH HEIGHT] [SECONDS] [options]
       raytracer SCENE [WIDTH HEIGHT] [SECONDS] --resume FILE.exr [--spp N] [options]
       raytracer merge OUT.exr IN.exr... [--png FILE.png] [--stats-output FILE]
       raytracer info FILE

Renders SCENE (a .in scene file) by path tracing on the GPU, WIDTH x HEIGHT pixels
(default 640 480). Without SECONDS or --spp a window shows the image converging until it
is closed (Escape closes it; its panel, Tab, lists the keys and mouse actions). With
SECONDS the render runs that long, then writes the tone-mapped image as SCENE-NAME.ppm in
the current folder (or --output). Without a display, or with --headless, rendering uses
OSMesa and opens no window. Each option may be given once.

EXR and PNG files describe themselves in their headers (samples, seeds, settings, the
scene's SHA-256, the program); an EXR also holds each pixel's sample count and second
moments, so that renders can be merged and resumed (docs/SCALE_OUT.md):
  merge                 combines renders of one scene, size and settings into OUT.exr, as
                        one render of all their samples would; refuses (one line, nothing
                        written) inputs that differ or share samples of one seed.
                        --png FILE: the tone-mapped picture too; --stats-output FILE: the
                        merged statistics
  info                  prints what a file says of itself

output:
  --spp N               stop after exactly N samples per pixel (deterministic for a seed);
                        with --target-error, the most a pixel may take
  --target-error E      stop once the estimated error is E: the relative RMS error, as a
                        rel RMSE against the converged image (0.01 is 1 %), estimated from
                        the per-pixel variance with its uncertainty (docs/ACCURACY.md). The
                        samples go where the error is (adaptive sampling): a tile of pixels
                        stops once it holds its share. With SECONDS or --spp, whichever comes
                        first; the summary says which, and the error reached
  --min-spp N           with --target-error, the samples every pixel takes before it may
                        stop (default 32), so that a rare bright path is not missed
  --adaptive-tile N     with --target-error, pixels along the side of a tile that stops as
                        one (default 8; 1: every pixel alone)
  --uniform-sampling    with --target-error, every pixel takes the same samples
)"
           + outputFormatsHelp() + R"(
  --stats-output FILE   also write per-pixel statistics (.exr or .pfm): samples, discarded
                        samples, variance of the mean. The image and the statistics are
                        written together or not at all; an interrupted render marks them
                        (attribute raytracer:interrupted, where the format holds attributes)
  --resume FILE         go on from the render FILE (an .exr written by this program) until
                        it holds --spp N samples per pixel in all, or for SECONDS more, with
                        new samples only; writes FILE again (or --output). The scene, size
                        and image-changing settings must be FILE's; WIDTH HEIGHT default to
                        FILE's, --seed to its first seed. Renders headless
  --headless            render with OSMesa even when a display is available
  --seed N              random seed (default 1)
  --samples-per-frame N paths per pixel per frame (default: chosen so that a frame takes
                        about 0.5 s in a batch render, 0.15 s in a window, at most 16)
  --band-seconds S      draw frames in bands of about S seconds each, so a render stops
                        or a window responds between them (default 0.25; 0: whole frames)
  --quiet               no progress line

accuracy (see docs/ACCURACY.md for what each costs):
  --hit-tolerance F     accept a hit within F pixel footprints (default 0.25)
  --max-steps N         sphere-tracing step limit per ray (default 512)
  --over-relaxation W   over-relaxation factor, 1 to < 2 (default 1.2; 1 disables it)
  --step-scale F        multiply every sphere-tracing step by F in (0, 1] (default 1):
                        conservative steps for user SDFs that overestimate distances
  --max-bounces N       scattering events per path (default 16)
  --rr-depth N          bounces before Russian roulette may end a path (default 4)
  --no-mis              light sampling only for sphere lights, no multiple importance sampling
  --fresnel MODEL       dielectric Fresnel: schlick (default) or exact
  --sampler KIND        sobol (default): Owen-scrambled Sobol points for the pixel and the
                        first four bounces; independent: random numbers for every decision

shader:
  --features            print the features SCENE uses and exit
  --print-shader        print the fragment shader assembled for SCENE and exit
  --no-specialize       use the general shader with every feature instead of one built
                        for the scene
  --no-culling          march every ray against every object (culling the objects a ray
                        cannot come near is exact; this only shows what it saves)
  --exact-geometry      find surfaces by exact ray intersection instead of sphere tracing
                        (spheres, polyhedra, boxes, cylinders, disks, cones, tori no thinner
                        than 1:10, user SDFs with an @intersect function): the reference for
                        the sphere tracer's geometric error (docs/ACCURACY.md)

  --help                this text
  --version             the program's version
)";
}

}  // namespace app
