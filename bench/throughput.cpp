// Where the time goes, per scene: what a path costs in march steps (camera rays, rays after
// a diffuse or glossy bounce, shadow rays), shadow rays and segments per path, the distance
// evaluations outside marches, the share of llvmpipe's lockstep lanes left waiting, and the
// time per path and per march step. Prints a Markdown table (docs/PERFORMANCE.md).
//
//   bench_throughput [--size W H] [--seconds S] [--profile-spp N] [--dump PREFIX] [SETTINGS...]
//                    SCENE...
//
// --dump writes PREFIX-SCENE-steps-per-path.pfm (march steps per path by kind of ray, per
// pixel) and prints their spread over the pixels.
//
// The counts come from a shader built to count its work (RenderSettings::profileCounters,
// shaders/modules/work_counters.glsl): deterministic for a seed, whatever else the machine
// does. The times come from the ordinary shader, rendering for S seconds after a warm-up
// frame, with the program's own choice of paths per frame; they are this machine's, at
// this moment (compare them only within one run).
//
// Lockstep: llvmpipe shades 8 pixels at once (a 4 x 2 block in one SIMD vector), and a loop
// runs until its slowest lane is done. Over a frame, a block costs at least 8 times the work
// of its busiest pixel; "lanes idle" is 1 - (the pixels' work) / (that cost), a lower bound
// on the waste (within a frame the busiest pixel changes from segment to segment, which
// costs more still).
#include "io/ImageFile.h"
#include "platform/OsMesaContext.h"
#include "render/ProgressiveRenderer.h"
#include "scene/SceneParser.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <string>
#include <vector>

namespace {

struct WorkPerPath {
    double cameraSteps = 0, bounceSteps = 0, shadowSteps = 0;
    double shadowRays = 0, segments = 0, evaluations = 0;
    double lanesIdle = 0;
};

WorkPerPath countWork(const scene::Scene& scene, int width, int height, int samples,
                      settings::RenderSettings settings, const std::string& dumpPrefix)
{
    settings.profileCounters = true;
    settings.secondsPerBand = 0.0;
    render::ProgressiveRenderer renderer(scene, width, height, settings);
    while (renderer.samplesPerPixel() < samples)
        renderer.renderFrame({}, std::min(8, samples - renderer.samplesPerPixel()));
    renderer.completeSamples();
    const auto [counts, more] = renderer.accumulationTargets();
    // The work per pixel as images, and the spread of the march steps per path over the
    // pixels: a heavy tail is what lockstep pays for.
    if (!dumpPrefix.empty()) {
        io::Image perPathSteps(width, height, 3);
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x)
                for (int channel = 0; channel < 3; ++channel)
                    perPathSteps.at(x, y, channel) = counts.at(x, y, channel) / counts.at(x, y, 3);
        io::writeImage(dumpPrefix + "-steps-per-path.pfm", perPathSteps);
        const char* kinds[] = {"camera", "bounce", "shadow"};
        for (int channel = 0; channel < 3; ++channel) {
            std::vector<double> perPath;
            for (int y = 0; y < height; ++y)
                for (int x = 0; x < width; ++x)
                    perPath.push_back(counts.at(x, y, channel) / counts.at(x, y, 3));
            std::sort(perPath.begin(), perPath.end());
            std::fprintf(stderr, "%s %s steps per path: median %.1f p90 %.1f p99 %.1f max %.1f\n",
                         dumpPrefix.c_str(), kinds[channel], perPath[perPath.size() / 2],
                         perPath[perPath.size() * 9 / 10], perPath[perPath.size() * 99 / 100],
                         perPath.back());
        }
    }
    WorkPerPath work;
    double paths = 0.0, lanes = 0.0, busiest = 0.0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            work.cameraSteps += counts.at(x, y, 0);
            work.bounceSteps += counts.at(x, y, 1);
            work.shadowSteps += counts.at(x, y, 2);
            paths += counts.at(x, y, 3);
            work.shadowRays += more.at(x, y, 0);
            work.segments += more.at(x, y, 1);
            work.evaluations += more.at(x, y, 2);
        }
    // Per 4 x 2 block: its pixels' total steps, against 8 times its busiest pixel's.
    for (int y0 = 0; y0 < height; y0 += 2)
        for (int x0 = 0; x0 < width; x0 += 4) {
            double maximum = 0.0;
            for (int y = y0; y < std::min(height, y0 + 2); ++y)
                for (int x = x0; x < std::min(width, x0 + 4); ++x) {
                    const double steps = counts.at(x, y, 0) + counts.at(x, y, 1) +
                                         counts.at(x, y, 2) + more.at(x, y, 2);
                    lanes += steps;
                    maximum = std::max(maximum, steps);
                }
            busiest += 8.0 * maximum;
        }
    for (double* value : {&work.cameraSteps, &work.bounceSteps, &work.shadowSteps, &work.shadowRays,
                          &work.segments, &work.evaluations})
        *value /= paths;
    work.lanesIdle = busiest > 0.0 ? 1.0 - lanes / busiest : 0.0;
    return work;
}

double megapathsPerSecond(const scene::Scene& scene, int width, int height, double seconds,
                          const settings::RenderSettings& settings)
{
    render::ProgressiveRenderer renderer(scene, width, height, settings);
    renderer.renderFrame({}, 1);
    int samplesPerFrame = 1;
    double elapsed = 0.0;
    int samples = 0;
    const auto start = std::chrono::steady_clock::now();
    while (elapsed < seconds) {
        renderer.renderFrame({}, samplesPerFrame);
        samples += samplesPerFrame;
        // The program's own choice: frames of about half a second, at most 16 paths.
        samplesPerFrame = std::clamp(
            static_cast<int>(0.5 / std::max(renderer.lastSecondsPerSample(), 1e-6)), 1, 16);
        elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    return static_cast<double>(width) * height * samples / elapsed / 1e6;
}

[[noreturn]] void usage()
{
    std::fprintf(stderr, "usage: bench_throughput [--size W H] [--seconds S] [--profile-spp N] "
                         "[--no-culling] [--sampler independent] [--dump PREFIX] SCENE...\n");
    std::exit(2);
}

}  // namespace

int main(int argc, char* argv[])
{
    int width = 400, height = 300, profileSamples = 8;
    double seconds = 6.0;
    settings::RenderSettings settings;
    std::vector<std::string> scenes;
    std::string dumpPrefix;
    for (int i = 1; i < argc; ++i) {
        const std::string argument = argv[i];
        if (argument == "--size" && i + 2 < argc) {
            width = std::atoi(argv[++i]);
            height = std::atoi(argv[++i]);
        } else if (argument == "--seconds" && i + 1 < argc) {
            seconds = std::atof(argv[++i]);
        } else if (argument == "--dump" && i + 1 < argc) {
            dumpPrefix = argv[++i];
        } else if (argument == "--profile-spp" && i + 1 < argc) {
            profileSamples = std::atoi(argv[++i]);
        } else if (argument == "--no-culling") {
            settings.rayCulling = false;
        } else if (argument == "--sampler" && i + 1 < argc) {
            settings.sampler = std::string(argv[++i]) == "independent"
                                   ? settings::SamplerKind::Independent
                                   : settings::SamplerKind::Sobol;
        } else if (!argument.empty() && argument[0] == '-') {
            usage();
        } else {
            scenes.push_back(argument);
        }
    }
    if (scenes.empty())
        usage();
    platform::OsMesaContext context;
    std::printf("| scene | camera steps | bounce steps | shadow steps | shadow rays | segments | "
                "other evaluations | lanes idle | Mpaths/s | ns per step |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
    for (const std::string& path : scenes) {
        const scene::Scene scene = scene::parseSceneFile(path);
        const WorkPerPath work = countWork(
            scene, width, height, profileSamples, settings,
            dumpPrefix.empty() ? ""
                               : dumpPrefix + "-" + std::filesystem::path(path).stem().string());
        const double rate = megapathsPerSecond(scene, width, height, seconds, settings);
        const double steps = work.cameraSteps + work.bounceSteps + work.shadowSteps;
        std::printf("| %s | %.1f | %.1f | %.1f | %.2f | %.2f | %.1f | %.0f %% | %.3f | %.1f |\n",
                    path.c_str(), work.cameraSteps, work.bounceSteps, work.shadowSteps,
                    work.shadowRays, work.segments, work.evaluations, 100.0 * work.lanesIdle, rate,
                    1e3 / (rate * steps));
    }
    const std::time_t now = std::time(nullptr);
    char date[32];
    std::strftime(date, sizeof date, "%F", std::gmtime(&now));
    std::printf("(%dx%d; counts per path from %d spp; time from %.0f s of rendering; %s)\n", width,
                height, profileSamples, seconds, date);
}
