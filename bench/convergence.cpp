// What accuracy costs in time: error against a converged reference as a function of render
// time and of every accuracy setting, per scene (issue 7; docs/ACCURACY.md is made from the
// CSVs this writes, by tools/accuracy-report.sh).
//
//   bench_convergence [options] SCENE...
//
// Three measurements, each against a high-spp reference rendered with the default settings
// and a fixed seed (cached in --cache, keyed by everything that decides its pixels):
//   convergence  spp = 1, 2, 4, ... --max-spp with another seed: render time, Mpaths/s,
//                error, and the noise of the image itself;
//   settings     one accuracy setting varied at a time from the defaults, --settings-spp
//                each: time per sample and the error left, which above the noise is bias;
//   equal-time   the error reached after --budgets seconds of rendering at --budget-size.
// Render time never includes the shader compile nor the first draw, where llvmpipe
// generates machine code: each renderer draws one warm-up frame, which is timed apart and
// then thrown away.
//
// Errors, both over every pixel and colour channel:
//   relative MSE  mean of (x - ref)^2 / (ref^2 + eps) on linear radiance, eps = 0.01 (the
//                 relative MSE of the Monte Carlo denoising literature, e.g. Rousselle,
//                 Knaus and Zwicker 2011); see kRelativeMseEpsilon for the choice of eps;
//   tone RMSE     root mean square difference of the displayed pictures on the 0..255 scale,
//                 after the display's tone curve (film/ToneCurve.h) in double, not
//                 rounded to 8 bits, so that differences under one level still show.
//
// The noise of an image that is the mean of n samples is measured without a second render:
// the same run's image at n/2 samples, H, and at n, M, give the second half's mean
// B = 2M - H, independent of H, and M - H = (B - H)/2, whose square has expectation
// Var(M). So mean((M - H)^2 / (ref^2 + eps)) estimates the relative MSE that noise alone
// puts in M; an error well above the noise of both image and reference is bias.
#include "convergence/ImageErrors.h"
#include "convergence/References.h"
#include "convergence/TimedRenderer.h"
#include "io/ImageFile.h"
#include "platform/OsMesaContext.h"
#include "render/ProgressiveRenderer.h"
#include "scene/FileLookup.h"
#include "scene/SceneParser.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace fs = std::filesystem;

namespace {

using namespace convergence;

// ---------------------------------------------------------------------------------------
// Settings

bool sameSettings(const settings::RenderSettings& a, const settings::RenderSettings& b)
{
    return a.hitTolerance == b.hitTolerance && a.maxMarchSteps == b.maxMarchSteps &&
           a.overRelaxation == b.overRelaxation && a.stepScale == b.stepScale &&
           a.maxBounces == b.maxBounces && a.russianRouletteDepth == b.russianRouletteDepth &&
           a.multipleImportanceSampling == b.multipleImportanceSampling &&
           a.dielectricFresnel == b.dielectricFresnel && a.variant == b.variant;
}

struct SettingValue {
    double value;       // for the plots' axes (categories are numbered)
    std::string label;  // as the command line spells it
    std::function<void(settings::RenderSettings&)> apply;
};

// One accuracy setting, named as the raytracer's option for it, and the values it is
// swept over.
struct SettingSweep {
    std::string name;
    std::vector<SettingValue> values;
};

std::vector<SettingSweep> accuracySettingSweeps()
{
    using settings::RenderSettings;
    std::vector<SettingSweep> sweeps;
    auto numeric = [&](const std::string& name, std::vector<double> values,
                       std::function<void(RenderSettings&, double)> set) {
        SettingSweep sweep{name, {}};
        for (double v : values)
            sweep.values.push_back(
                {v, formatNumber(v), [set, v](RenderSettings& s) { set(s, v); }});
        sweeps.push_back(sweep);
    };
    numeric("hit-tolerance", {0.0625, 0.125, 0.25, 0.5, 1},
            [](RenderSettings& s, double v) { s.hitTolerance = static_cast<float>(v); });
    numeric("max-steps", {32, 64, 128, 256, 512},
            [](RenderSettings& s, double v) { s.maxMarchSteps = static_cast<int>(v); });
    numeric("max-bounces", {1, 2, 4, 8, 16},
            [](RenderSettings& s, double v) { s.maxBounces = static_cast<int>(v); });
    numeric("rr-depth", {0, 1, 2, 4, 8},
            [](RenderSettings& s, double v) { s.russianRouletteDepth = static_cast<int>(v); });
    numeric("over-relaxation", {1.0, 1.2, 1.5},
            [](RenderSettings& s, double v) { s.overRelaxation = static_cast<float>(v); });
    numeric("step-scale", {0.5, 0.75, 1.0},
            [](RenderSettings& s, double v) { s.stepScale = static_cast<float>(v); });
    auto setMis = [](bool on) {
        return [on](RenderSettings& s) { s.multipleImportanceSampling = on; };
    };
    sweeps.push_back({"mis", {{1, "on", setMis(true)}, {0, "off", setMis(false)}}});
    auto setFresnel = [](settings::FresnelModel model) {
        return [model](RenderSettings& s) { s.dielectricFresnel = model; };
    };
    sweeps.push_back({"fresnel",
                      {{0, "schlick", setFresnel(settings::FresnelModel::Schlick)},
                       {1, "exact", setFresnel(settings::FresnelModel::Exact)}}});
    return sweeps;
}

// ---------------------------------------------------------------------------------------
// Output

// A CSV file written row by row and flushed, so that a long run interrupted keeps its rows.
class CsvFile {
public:
    CsvFile(const fs::path& path, const std::string& header) : file_(path)
    {
        if (!file_)
            throw std::runtime_error("cannot write " + path.string());
        file_ << header << "\n" << std::flush;
    }
    void row(const std::vector<std::string>& cells)
    {
        for (std::size_t i = 0; i < cells.size(); ++i)
            file_ << (i ? "," : "") << cells[i];
        file_ << "\n" << std::flush;
    }

private:
    std::ofstream file_;
};

std::string cell(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    return text;
}

std::string cell(long long value)
{
    return std::to_string(value);
}

std::string loadAverage()
{
    std::ifstream file("/proc/loadavg");
    std::string oneMinute;
    file >> oneMinute;
    return oneMinute.empty() ? "unknown" : oneMinute;
}

std::string currentTime()
{
    const std::time_t now = std::time(nullptr);
    char text[64];
    std::strftime(text, sizeof text, "%Y-%m-%d %H:%M:%S UTC", std::gmtime(&now));
    return text;
}

// ---------------------------------------------------------------------------------------
// The three measurements

struct Options {
    std::vector<fs::path> scenes;
    int width = 320;
    int height = 240;
    int maxSamplesPerPixel = 512;
    int settingsSamplesPerPixel = 256;
    std::vector<double> budgets = {1, 10, 60};
    int budgetWidth = 320;
    int budgetHeight = 240;
    int samplesPerFrame = 0;  // 0: defaultSamplesPerFrame for the size
    std::uint64_t seed = 2;
    std::vector<std::string> settingNames;  // empty: every setting
    bool convergence = true;
    bool settings = true;
    bool equalTime = true;
    ReferenceOptions reference;
    fs::path outputDirectory = ".";
};

int samplesPerFrameFor(const Options& options, int width, int height)
{
    return options.samplesPerFrame > 0 ? options.samplesPerFrame
                                       : defaultSamplesPerFrame(width, height);
}

void measureConvergence(const scene::Scene& scene, const Reference& reference,
                        const Options& options, CsvFile& csv)
{
    const std::string name = sceneName(scene.sourcePath);
    settings::RenderSettings settings;
    settings.seed = options.seed;
    TimedRenderer run(scene, options.width, options.height, settings,
                      samplesPerFrameFor(options, options.width, options.height));
    std::printf("\n%s, %dx%d: compile %.2f s, warm-up frame %.2f s (not counted); reference "
                "%d spp, its noise: relative MSE %.3g, tone RMSE %.3g\n",
                name.c_str(), options.width, options.height, run.compileSeconds(),
                run.warmUpSeconds(), reference.samplesPerPixel, reference.noise.relativeMse,
                reference.noise.toneMappedRmse);
    std::printf("%8s %10s %10s %10s %9s %12s %12s %12s %10s\n", "spp", "seconds", "cpu s", "ms/spp",
                "Mpaths/s", "rel. MSE", "its noise", "tone RMSE", "discarded");
    io::Image previous;
    for (int spp = 1; spp <= options.maxSamplesPerPixel; spp *= 2) {
        run.renderTo(spp);
        const io::Image image = run.renderer().radiance();
        const ImageError error = errorAgainst(image, reference.image);
        std::optional<ImageError> noise;
        if (spp >= 2)
            noise = noiseOfMean(previous, image, reference.image);
        const auto discarded = static_cast<long long>(run.renderer().discardedSamples());
        std::printf("%8d %10.3f %10.3f %10.3f %9.4f %12.4g %12s %12.4g %10lld\n", spp,
                    run.renderSeconds(), run.cpuSeconds(), 1e3 * run.renderSeconds() / spp,
                    run.megapathsPerSecond(), error.relativeMse,
                    noise ? cell(noise->relativeMse).c_str() : "-", error.toneMappedRmse,
                    discarded);
        std::fflush(stdout);
        csv.row({name, cell(static_cast<long long>(options.width)),
                 cell(static_cast<long long>(options.height)), cell(static_cast<long long>(spp)),
                 cell(run.renderSeconds()), cell(run.cpuSeconds()),
                 cell(1e3 * run.renderSeconds() / spp), cell(run.megapathsPerSecond()),
                 cell(error.relativeMse), cell(error.toneMappedRmse),
                 noise ? cell(noise->relativeMse) : "", noise ? cell(noise->toneMappedRmse) : "",
                 cell(reference.noise.relativeMse), cell(reference.noise.toneMappedRmse),
                 cell(discarded), cell(run.compileSeconds()), cell(run.warmUpSeconds())});
        previous = image;
    }
}

struct SettingRun {
    io::Image image;
    double renderSeconds = 0.0;
    double cpuSeconds = 0.0;
    double megapathsPerSecond = 0.0;
    double compileSeconds = 0.0;
    double warmUpSeconds = 0.0;
    ImageError error;
    ImageError noise;
    double brightnessBias = 0.0;
    double brightnessNoise = 0.0;  // of this image and the reference together
    long long discarded = 0;
};

SettingRun runSetting(const scene::Scene& scene, const settings::RenderSettings& settings,
                      const Reference& reference, const Options& options)
{
    TimedRenderer run(scene, options.width, options.height, settings,
                      samplesPerFrameFor(options, options.width, options.height));
    run.renderTo(std::max(1, options.settingsSamplesPerPixel / 2));
    const io::Image half = run.renderer().radiance();
    run.renderTo(options.settingsSamplesPerPixel);
    SettingRun result;
    result.image = run.renderer().radiance();
    result.renderSeconds = run.renderSeconds();
    result.cpuSeconds = run.cpuSeconds();
    result.megapathsPerSecond = run.megapathsPerSecond();
    result.compileSeconds = run.compileSeconds();
    result.warmUpSeconds = run.warmUpSeconds();
    result.error = errorAgainst(result.image, reference.image);
    result.noise = noiseOfMean(half, result.image, reference.image);
    result.brightnessBias = brightnessBias(result.image, reference.image);
    const double ownNoise =
        brightnessNoise(run.renderer().sampleStatistics(), imageSum(reference.image));
    result.brightnessNoise = std::hypot(ownNoise, reference.brightnessNoise);
    result.discarded = static_cast<long long>(run.renderer().discardedSamples());
    return result;
}

void measureSettings(const scene::Scene& scene, const Reference& reference, const Options& options,
                     CsvFile& csv)
{
    const std::string name = sceneName(scene.sourcePath);
    const int spp = options.settingsSamplesPerPixel;
    std::printf("\n%s, %dx%d, %d spp per setting, against the default-settings reference "
                "(%d spp; its noise: relative MSE %.3g, tone RMSE %.3g).\n"
                "excess = rel. MSE - noise of the image - noise of the reference: bias "
                "squared, where it stands clear of the noise. brightness: image sum / "
                "reference sum - 1, and its noise (one standard deviation).\n",
                name.c_str(), options.width, options.height, spp, reference.samplesPerPixel,
                reference.noise.relativeMse, reference.noise.toneMappedRmse);
    std::printf("%-16s %8s %9s %9s %9s %9s %11s %11s %11s %10s %18s %9s\n", "setting", "value",
                "seconds", "ms/spp", "cpu ms/spp", "Mpaths/s", "rel. MSE", "its noise", "excess",
                "tone RMSE", "brightness", "discarded");
    settings::RenderSettings defaults;
    defaults.seed = options.seed;
    // The same in every sweep: rendered once. With the same seed, a setting that leaves the
    // image bit for bit the same does nothing in this scene (MIS without sphere lights,
    // Fresnel without glass); its time differs from the default's only by the machine's noise.
    const SettingRun defaultRun = runSetting(scene, defaults, reference, options);
    for (const SettingSweep& sweep : accuracySettingSweeps()) {
        if (!options.settingNames.empty() &&
            std::find(options.settingNames.begin(), options.settingNames.end(), sweep.name) ==
                options.settingNames.end())
            continue;
        for (const SettingValue& value : sweep.values) {
            settings::RenderSettings settings = defaults;
            value.apply(settings);
            const bool isDefault = sameSettings(settings, defaults);
            const SettingRun result =
                isDefault ? defaultRun : runSetting(scene, settings, reference, options);
            const bool sameImage = result.image.pixels == defaultRun.image.pixels;
            const double excess =
                result.error.relativeMse - result.noise.relativeMse - reference.noise.relativeMse;
            const double msPerSample = 1e3 * result.renderSeconds / spp;
            std::printf("%-16s %8s %9.3f %9.3f %9.3f %9.4f %11.4g %11.4g %11.3g %10.4g "
                        "%+9.4f +-%.4f %9lld%s\n",
                        sweep.name.c_str(), value.label.c_str(), result.renderSeconds, msPerSample,
                        1e3 * result.cpuSeconds / spp, result.megapathsPerSecond,
                        result.error.relativeMse, result.noise.relativeMse, excess,
                        result.error.toneMappedRmse, result.brightnessBias, result.brightnessNoise,
                        result.discarded,
                        isDefault   ? "  (default)"
                        : sameImage ? "  (same image)"
                                    : "");
            std::fflush(stdout);
            csv.row({name,
                     sweep.name,
                     cell(value.value),
                     value.label,
                     isDefault ? "1" : "0",
                     sameImage ? "1" : "0",
                     cell(static_cast<long long>(options.width)),
                     cell(static_cast<long long>(options.height)),
                     cell(static_cast<long long>(spp)),
                     cell(result.renderSeconds),
                     cell(result.cpuSeconds),
                     cell(msPerSample),
                     cell(1e3 * result.cpuSeconds / spp),
                     cell(result.megapathsPerSecond),
                     cell(result.error.relativeMse),
                     cell(result.error.toneMappedRmse),
                     cell(result.noise.relativeMse),
                     cell(result.noise.toneMappedRmse),
                     cell(reference.noise.relativeMse),
                     cell(reference.noise.toneMappedRmse),
                     cell(excess),
                     cell(result.brightnessBias),
                     cell(result.brightnessNoise),
                     cell(result.discarded),
                     cell(result.compileSeconds),
                     cell(result.warmUpSeconds)});
        }
    }
}

void measureEqualTime(const scene::Scene& scene, const Reference& reference, const Options& options,
                      CsvFile& csv)
{
    const std::string name = sceneName(scene.sourcePath);
    settings::RenderSettings settings;
    settings.seed = options.seed;
    TimedRenderer run(scene, options.budgetWidth, options.budgetHeight, settings,
                      samplesPerFrameFor(options, options.budgetWidth, options.budgetHeight));
    std::printf("\n%s, %dx%d, equal time (reference %d spp; its noise: relative MSE %.3g)\n",
                name.c_str(), options.budgetWidth, options.budgetHeight, reference.samplesPerPixel,
                reference.noise.relativeMse);
    std::printf("%10s %10s %8s %9s %12s %12s\n", "budget s", "used s", "spp", "Mpaths/s",
                "rel. MSE", "tone RMSE");
    std::vector<double> budgets = options.budgets;
    std::sort(budgets.begin(), budgets.end());
    for (double budget : budgets) {
        run.renderUntil(budget);
        const io::Image image = run.renderer().radiance();
        const ImageError error = errorAgainst(image, reference.image);
        const double megapaths = static_cast<double>(options.budgetWidth) * options.budgetHeight *
                                 run.samplesPerPixel() / std::max(run.secondsAtLastFrame(), 1e-9) /
                                 1e6;
        std::printf("%10g %10.3f %8d %9.4f %12.4g %12.4g\n", budget, run.secondsAtLastFrame(),
                    run.samplesPerPixel(), megapaths, error.relativeMse, error.toneMappedRmse);
        std::fflush(stdout);
        csv.row({name, cell(static_cast<long long>(options.budgetWidth)),
                 cell(static_cast<long long>(options.budgetHeight)), cell(budget),
                 cell(run.secondsAtLastFrame()), cell(run.cpuSeconds()),
                 cell(static_cast<long long>(run.samplesPerPixel())), cell(megapaths),
                 cell(error.relativeMse), cell(error.toneMappedRmse),
                 cell(reference.noise.relativeMse), cell(reference.noise.toneMappedRmse)});
    }
}

// ---------------------------------------------------------------------------------------
// Command line

const char* const kUsage =
    "usage: bench_convergence [options] SCENE...\n"
    "  --mode LIST             convergence,settings,equal-time (default: all three)\n"
    "  --size W H              size for convergence and settings (default 320 240)\n"
    "  --reference-spp N       reference samples per pixel (default 4096)\n"
    "  --max-spp N             convergence sweep 1, 2, 4, ... N (default 512)\n"
    "  --settings-spp N        samples per pixel of each setting's render (default 256)\n"
    "  --settings LIST         settings to sweep (default all): hit-tolerance, max-steps,\n"
    "                          max-bounces, rr-depth, over-relaxation, step-scale, mis, fresnel\n"
    "  --budgets LIST          equal-time budgets in seconds (default 1,10,60)\n"
    "  --budget-size W H       size for the equal-time view (default 320 240)\n"
    "  --samples-per-frame N   paths per pixel per draw (default: 1 at 320x240, more when\n"
    "                          smaller)\n"
    "  --seed N                seed of the measured renders (default 2)\n"
    "  --reference-seed N      seed of the references (default 1)\n"
    "  --cache DIR             reference cache (default: bench-convergence-cache)\n"
    "  --refresh-references    render the references even when cached\n"
    "  --output DIR            where the CSVs go (default: the current folder)\n";

std::vector<std::string> splitList(const std::string& text)
{
    std::vector<std::string> items;
    std::stringstream stream(text);
    std::string item;
    while (std::getline(stream, item, ','))
        if (!item.empty())
            items.push_back(item);
    return items;
}

int positiveInteger(const std::string& text, const std::string& what)
{
    std::size_t used = 0;
    int value = 0;
    try {
        value = std::stoi(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != text.size() || value < 1)
        throw std::runtime_error(what + " must be a whole number of 1 or more, not '" + text + "'");
    return value;
}

Options parseOptions(int argc, char* argv[])
{
    Options options;
    options.reference.cacheDirectory = "bench-convergence-cache";
    for (int i = 1; i < argc; ++i) {
        const std::string argument = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc)
                throw std::runtime_error(argument + " needs a value");
            return argv[++i];
        };
        if (argument == "--mode") {
            options.convergence = options.settings = options.equalTime = false;
            for (const std::string& mode : splitList(value())) {
                if (mode == "convergence")
                    options.convergence = true;
                else if (mode == "settings")
                    options.settings = true;
                else if (mode == "equal-time")
                    options.equalTime = true;
                else
                    throw std::runtime_error("unknown mode '" + mode + "'");
            }
        } else if (argument == "--size") {
            options.width = positiveInteger(value(), "width");
            options.height = positiveInteger(value(), "height");
        } else if (argument == "--budget-size") {
            options.budgetWidth = positiveInteger(value(), "width");
            options.budgetHeight = positiveInteger(value(), "height");
        } else if (argument == "--reference-spp") {
            options.reference.samplesPerPixel = positiveInteger(value(), argument);
        } else if (argument == "--max-spp") {
            options.maxSamplesPerPixel = positiveInteger(value(), argument);
        } else if (argument == "--settings-spp") {
            options.settingsSamplesPerPixel = positiveInteger(value(), argument);
        } else if (argument == "--settings") {
            options.settingNames = splitList(value());
            for (const std::string& name : options.settingNames) {
                const auto sweeps = accuracySettingSweeps();
                if (std::none_of(sweeps.begin(), sweeps.end(),
                                 [&](const SettingSweep& s) { return s.name == name; }))
                    throw std::runtime_error("unknown setting '" + name + "'");
            }
        } else if (argument == "--budgets") {
            options.budgets.clear();
            for (const std::string& budget : splitList(value()))
                options.budgets.push_back(std::stod(budget));
        } else if (argument == "--samples-per-frame") {
            options.samplesPerFrame = positiveInteger(value(), argument);
        } else if (argument == "--seed") {
            options.seed = std::stoull(value());
        } else if (argument == "--reference-seed") {
            options.reference.seed = std::stoull(value());
        } else if (argument == "--cache") {
            options.reference.cacheDirectory = value();
        } else if (argument == "--refresh-references") {
            options.reference.refresh = true;
        } else if (argument == "--output") {
            options.outputDirectory = value();
        } else if (argument == "--help" || argument == "-h") {
            std::fputs(kUsage, stdout);
            std::exit(0);
        } else if (!argument.empty() && argument[0] == '-') {
            throw std::runtime_error("unknown option '" + argument + "' (see --help)");
        } else {
            options.scenes.push_back(argument);
        }
    }
    if (options.scenes.empty())
        throw std::runtime_error("no scene given (see --help)");
    if (options.seed == options.reference.seed)
        throw std::runtime_error("--seed and --reference-seed must differ: an image compared "
                                 "with a reference of the same random numbers shows no noise");
    return options;
}

}  // namespace

int main(int argc, char* argv[])
{
    try {
        const Options options = parseOptions(argc, argv);
        const auto start = std::chrono::steady_clock::now();
        platform::OsMesaContext context;
        fs::create_directories(options.outputDirectory);

        CsvFile runInformation(options.outputDirectory / "run.csv", "key,value");
        std::string commandLine;
        for (int i = 0; i < argc; ++i)
            commandLine += (i ? " " : "") + std::string(argv[i]);
        runInformation.row({"gl", "\"" + context.description() + "\""});
        runInformation.row({"hardware_threads",
                            cell(static_cast<long long>(std::thread::hardware_concurrency()))});
        runInformation.row({"started", currentTime()});
        runInformation.row({"load_average_at_start", loadAverage()});
        runInformation.row({"command", "\"" + commandLine + "\""});
        runInformation.row({"relative_mse_epsilon", cell(kRelativeMseEpsilon)});
        std::printf("%s, %u hardware threads, load average %s\n", context.description().c_str(),
                    std::thread::hardware_concurrency(), loadAverage().c_str());
        std::fflush(stdout);  // before the references' progress on stderr

        std::optional<CsvFile> referencesCsv, convergenceCsv, settingsCsv, equalTimeCsv;
        referencesCsv.emplace(options.outputDirectory / "references.csv",
                              "scene,width,height,spp,seed,render_seconds,mpaths_per_s,"
                              "rel_mse_noise,tone_rmse_noise,discarded,compile_seconds,"
                              "warmup_seconds,cached,key");
        if (options.convergence)
            convergenceCsv.emplace(options.outputDirectory / "convergence.csv",
                                   "scene,width,height,spp,seconds,cpu_seconds,ms_per_spp,"
                                   "mpaths_per_s,rel_mse,tone_rmse,rel_mse_noise,tone_rmse_noise,"
                                   "reference_rel_mse_noise,reference_tone_rmse_noise,"
                                   "discarded,compile_seconds,warmup_seconds");
        if (options.settings)
            settingsCsv.emplace(options.outputDirectory / "settings.csv",
                                "scene,setting,value,label,is_default,same_image_as_default,"
                                "width,height,spp,seconds,cpu_seconds,ms_per_spp,"
                                "cpu_ms_per_spp,mpaths_per_s,rel_mse,"
                                "tone_rmse,rel_mse_noise,tone_rmse_noise,"
                                "reference_rel_mse_noise,reference_tone_rmse_noise,"
                                "rel_mse_excess,brightness_bias,brightness_noise,discarded,"
                                "compile_seconds,warmup_seconds");
        if (options.equalTime)
            equalTimeCsv.emplace(options.outputDirectory / "equal_time.csv",
                                 "scene,width,height,budget_seconds,seconds,cpu_seconds,spp,"
                                 "mpaths_per_s,"
                                 "rel_mse,tone_rmse,reference_rel_mse_noise,"
                                 "reference_tone_rmse_noise");

        auto referenceFor = [&](const scene::Scene& scene, int width, int height) {
            const Reference reference = obtainReference(scene, width, height, options.reference);
            const double megapaths = static_cast<double>(width) * height *
                                     reference.samplesPerPixel /
                                     std::max(reference.renderSeconds, 1e-9) / 1e6;
            referencesCsv->row({sceneName(scene.sourcePath), cell(static_cast<long long>(width)),
                                cell(static_cast<long long>(height)),
                                cell(static_cast<long long>(reference.samplesPerPixel)),
                                cell(static_cast<long long>(options.reference.seed)),
                                cell(reference.renderSeconds), cell(megapaths),
                                cell(reference.noise.relativeMse),
                                cell(reference.noise.toneMappedRmse),
                                cell(static_cast<long long>(reference.discardedSamples)),
                                cell(reference.compileSeconds), cell(reference.warmUpSeconds),
                                reference.fromCache ? "1" : "0", reference.key});
            return reference;
        };

        for (const fs::path& path : options.scenes) {
            const scene::Scene scene = scene::parseSceneFile(path);
            std::optional<Reference> reference;
            if (options.convergence || options.settings) {
                reference = referenceFor(scene, options.width, options.height);
                if (options.convergence)
                    measureConvergence(scene, *reference, options, *convergenceCsv);
                if (options.settings)
                    measureSettings(scene, *reference, options, *settingsCsv);
            }
            if (options.equalTime) {
                if (!reference || reference->image.width != options.budgetWidth ||
                    reference->image.height != options.budgetHeight)
                    reference = referenceFor(scene, options.budgetWidth, options.budgetHeight);
                measureEqualTime(scene, *reference, options, *equalTimeCsv);
            }
        }
        runInformation.row({"finished", currentTime()});
        runInformation.row({"load_average_at_end", loadAverage()});
        runInformation.row({"total_seconds", cell(secondsSince(start))});
        return 0;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "bench_convergence: %s\n", error.what());
        return 1;
    }
}
