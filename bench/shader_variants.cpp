// Specialised versus general shader, per scene: million paths per second, compile and link
// time, and first-frame time (llvmpipe generates machine code at the first draw), each the
// median of several runs at one resolution. (Against the original program: only side by
// side, on this machine, in one run: bench/side-by-side.sh.)
//
//   bench_shader_variants [--size W H] [--seconds S] [--samples-per-frame K] [--repeats R]
//                         [--breakdown] [--markdown] SCENE...
//
// Each measurement renders for at least S seconds (default 3) after a first frame that is
// timed apart, with K paths per pixel per frame, or by default as many as the program itself
// would choose for a batch render (about half a second of frame, at most 16; see
// app/RenderCommand.cpp). The specialised shader is also measured with per-ray culling off
// (--no-culling), to show what culling buys. Mesa's shader cache is switched off so that
// every compile is real.
#include "platform/OsMesaContext.h"
#include "render/ProgressiveRenderer.h"
#include "scene/SceneParser.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

struct Measurement {
    double compileSeconds = 0.0;
    double firstFrameSeconds = 0.0;
    double firstDrawSeconds = 0.0;  // first frame minus one sample's rendering
    double megapathsPerSecond = 0.0;
};

double median(std::vector<double> values)
{
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// One renderer's first frame (one sample per pixel, with the driver's code generation),
// then frames of `samplesPerFrame` paths per pixel until `seconds` have passed.
Measurement measure(const scene::Scene& scene, settings::ShaderVariant variant, int width,
                    int height, int samplesPerFrame, double seconds, bool rayCulling = true)
{
    settings::RenderSettings settings;
    settings.variant = variant;
    settings.rayCulling = rayCulling;
    settings.secondsPerBand = 0.0;
    render::ProgressiveRenderer renderer(scene, width, height, settings);
    Measurement result;
    result.compileSeconds = renderer.compileSeconds();
    renderer.renderFrame({}, 1);
    const auto start = std::chrono::steady_clock::now();
    double elapsed = 0.0;
    int samples = 0;
    // The program's own choice when none is given: frames of about half a second.
    const bool chooseSamples = samplesPerFrame <= 0;
    int samplesThisFrame = chooseSamples ? 1 : samplesPerFrame;
    do {
        renderer.renderFrame({}, samplesThisFrame);
        samples += samplesThisFrame;
        elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (chooseSamples && renderer.lastSecondsPerSample() > 0.0)
            samplesThisFrame =
                std::clamp(static_cast<int>(0.5 / renderer.lastSecondsPerSample()), 1, 16);
    } while (elapsed < seconds);
    result.megapathsPerSecond = static_cast<double>(width) * height * samples / elapsed / 1e6;
    // The first frame is one sample plus the code generation at the first draw.
    result.firstFrameSeconds = renderer.firstFrameSeconds();
    result.firstDrawSeconds = std::max(0.0, result.firstFrameSeconds - elapsed / samples);
    return result;
}

}  // namespace

int main(int argc, char* argv[])
{
    int width = 400;
    int height = 300;
    double seconds = 3.0;
    int samplesPerFrame = 0;  // as the program chooses
    int repeats = 3;
    bool markdown = false;
    bool breakdown = false;
    std::vector<std::string> scenes;
    for (int i = 1; i < argc; ++i) {
        const std::string argument = argv[i];
        if (argument == "--size" && i + 2 < argc) {
            width = std::atoi(argv[++i]);
            height = std::atoi(argv[++i]);
        } else if (argument == "--seconds" && i + 1 < argc) {
            seconds = std::atof(argv[++i]);
        } else if (argument == "--samples-per-frame" && i + 1 < argc) {
            samplesPerFrame = std::atoi(argv[++i]);
        } else if (argument == "--repeats" && i + 1 < argc) {
            repeats = std::atoi(argv[++i]);
        } else if (argument == "--markdown") {
            markdown = true;
        } else if (argument == "--breakdown") {
            breakdown = true;
        } else {
            scenes.push_back(argument);
        }
    }
    if (scenes.empty()) {
        std::fprintf(stderr, "usage: bench_shader_variants [--size W H] [--seconds S] "
                             "[--samples-per-frame K] [--repeats R] [--breakdown] "
                             "[--markdown] SCENE...\n");
        return 2;
    }

    // Every compile must be a real one: Mesa would otherwise reuse code from earlier runs.
    setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
    platform::OsMesaContext context;
    const std::string perFrame = samplesPerFrame > 0 ? std::to_string(samplesPerFrame)
                                                     : std::string("the program's choice of");
    std::printf("%s\n%dx%d, at least %.1f s per run at %s paths per pixel per frame, median of "
                "%d runs\n\n",
                context.description().c_str(), width, height, seconds, perFrame.c_str(), repeats);
    const char* header =
        markdown ? "| scene | general Mpaths/s | specialised Mpaths/s | speed-up | specialised "
                   "without culling | culling's speed-up | compile+link "
                   "general / specialised (s) | first-draw code generation general / "
                   "specialised (s) |\n"
                   "|---|---|---|---|---|---|---|---|\n"
                 : "scene                 general  special  speed-up  unculled  culling  "
                   "compile g/s (s)  first draw g/s (s)\n";
    std::fputs(header, stdout);
    for (const std::string& path : scenes) {
        const scene::Scene scene = scene::parseSceneFile(path);
        std::vector<double> generalRate, specialRate, unculledRate, generalCompile, specialCompile,
            generalFirst, specialFirst, featuresRate, shapesRate;
        for (int r = 0; r < repeats; ++r) {
            if (breakdown) {
                featuresRate.push_back(measure(scene, settings::ShaderVariant::FeaturesOnly, width,
                                               height, samplesPerFrame, seconds)
                                           .megapathsPerSecond);
                shapesRate.push_back(measure(scene, settings::ShaderVariant::ShapesOnly, width,
                                             height, samplesPerFrame, seconds)
                                         .megapathsPerSecond);
            }
            // Interleaved so that load from elsewhere on the machine hits both alike.
            const Measurement general = measure(scene, settings::ShaderVariant::General, width,
                                                height, samplesPerFrame, seconds);
            const Measurement special = measure(scene, settings::ShaderVariant::Specialized, width,
                                                height, samplesPerFrame, seconds);
            const Measurement unculled = measure(scene, settings::ShaderVariant::Specialized, width,
                                                 height, samplesPerFrame, seconds, false);
            generalRate.push_back(general.megapathsPerSecond);
            unculledRate.push_back(unculled.megapathsPerSecond);
            specialRate.push_back(special.megapathsPerSecond);
            generalCompile.push_back(general.compileSeconds);
            specialCompile.push_back(special.compileSeconds);
            generalFirst.push_back(general.firstDrawSeconds);
            specialFirst.push_back(special.firstDrawSeconds);
        }
        const std::string name = std::filesystem::path(path).stem().string();
        const double g = median(generalRate);
        const double s = median(specialRate);
        const double u = median(unculledRate);
        if (markdown)
            std::printf("| %s | %.3f | %.3f | %.2fx | %.3f | %.2fx | %.2f / %.2f | %.2f / %.2f |\n",
                        name.c_str(), g, s, s / g, u, s / u, median(generalCompile),
                        median(specialCompile), median(generalFirst), median(specialFirst));
        else
            std::printf(
                "%-20s  %7.3f  %7.3f  %7.2fx  %8.3f  %6.2fx  %6.2f / %-6.2f  %7.2f / %-7.2f\n",
                name.c_str(), g, s, s / g, u, s / u, median(generalCompile), median(specialCompile),
                median(generalFirst), median(specialFirst));
        if (breakdown)
            std::printf("%-20s  features only %.3f, shapes only %.3f Mpaths/s\n", "",
                        median(featuresRate), median(shapesRate));
        std::fflush(stdout);
    }
    return 0;
}
