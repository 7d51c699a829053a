// What sampling an environment map buys: the same scene rendered with the map as a light
// (its distribution sampled, combined with BSDF sampling by MIS: the renderer's way) and with
// the map left to the rays that escape the scene (BSDF sampling alone: cosine-weighted for
// Lambertian surfaces), at equal samples and at equal error, and what a sample costs each
// way. Prints Markdown tables (docs/ACCURACY.md, "Environment maps").
//
//   bench_environment_sampling [--size W H] [--reference-spp N] [--spp N,N,...]
//                              [--rounds R] [--timing-spp N] SCENE
//
// The reference is the renderer's way at --reference-spp (seed 1); every measured render
// takes seed 2. The rel RMSE is sqrt(mean over pixels and channels of (x - ref)^2) over the
// mean of ref (docs/ACCURACY.md, "How it is measured"). Equal error: BSDF sampling's error at
// each sample count, interpolated on its log-log line, against the map sampled's error at
// the smallest count. Times: frames only (not compile nor the first frame), the two ways
// alternated --rounds times, medians.
#include "platform/OsMesaContext.h"
#include "render/ProgressiveRenderer.h"
#include "scene/SceneParser.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct Render {
    io::Image image;
    double secondsPerSample = 0.0;
};

Render renderScene(const scene::Scene& scene, int width, int height, int samples,
                   std::uint64_t seed)
{
    settings::RenderSettings settings;
    settings.seed = seed;
    settings.secondsPerBand = 0.0;
    render::ProgressiveRenderer renderer(scene, width, height, settings);
    // The first frame pays for the driver's code generation: timed apart and left out.
    renderer.renderFrame({}, 1);
    const auto start = std::chrono::steady_clock::now();
    while (renderer.samplesPerPixel() < samples)
        renderer.renderFrame({}, std::min(16, samples - renderer.samplesPerPixel()));
    renderer.completeSamples();
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return {renderer.radiance(), seconds / std::max(1, samples - 1)};
}

double relativeRmse(const io::Image& image, const io::Image& reference)
{
    double squares = 0.0;
    double sum = 0.0;
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        const double difference = image.pixels[i] - reference.pixels[i];
        squares += difference * difference;
        sum += reference.pixels[i];
    }
    const double count = static_cast<double>(image.pixels.size());
    return std::sqrt(squares / count) / (sum / count);
}

double brightness(const io::Image& image)
{
    double sum = 0.0;
    for (float value : image.pixels)
        sum += value;
    return sum;
}

double median(std::vector<double> values)
{
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

std::vector<int> parseCounts(const std::string& text)
{
    std::vector<int> counts;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ','))
        counts.push_back(std::atoi(item.c_str()));
    return counts;
}

}  // namespace

int main(int argc, char* argv[])
{
    int width = 128, height = 96, referenceSamples = 4096, rounds = 3, timingSamples = 64;
    std::vector<int> counts = {16, 64, 256, 1024};
    std::string scenePath;
    for (int i = 1; i < argc; ++i) {
        const std::string argument = argv[i];
        if (argument == "--size" && i + 2 < argc) {
            width = std::atoi(argv[++i]);
            height = std::atoi(argv[++i]);
        } else if (argument == "--reference-spp" && i + 1 < argc) {
            referenceSamples = std::atoi(argv[++i]);
        } else if (argument == "--spp" && i + 1 < argc) {
            counts = parseCounts(argv[++i]);
        } else if (argument == "--rounds" && i + 1 < argc) {
            rounds = std::atoi(argv[++i]);
        } else if (argument == "--timing-spp" && i + 1 < argc) {
            timingSamples = std::atoi(argv[++i]);
        } else if (scenePath.empty() && argument.rfind("--", 0) != 0) {
            scenePath = argument;
        } else {
            std::fprintf(stderr,
                         "usage: bench_environment_sampling [--size W H] [--reference-spp N] "
                         "[--spp N,N,...] [--rounds R] [--timing-spp N] SCENE\n");
            return 2;
        }
    }
    if (scenePath.empty() || counts.empty()) {
        std::fprintf(stderr, "bench_environment_sampling: a scene with an environment map\n");
        return 2;
    }
    try {
        platform::OsMesaContext context;
        const scene::Scene sampled = scene::parseSceneFile(scenePath);
        if (sampled.environment.kind != scene::EnvironmentKind::Map)
            throw std::runtime_error(scenePath + " has no environment map");
        scene::Scene escaping = sampled;
        escaping.environment.importanceSampled = false;

        std::printf("%s, %dx%d, reference: the map sampled, %d spp, seed 1\n\n", scenePath.c_str(),
                    width, height, referenceSamples);
        const io::Image reference = renderScene(sampled, width, height, referenceSamples, 1).image;

        std::printf("| spp | rel RMSE, map sampled (MIS) | rel RMSE, BSDF sampling alone | ratio "
                    "| samples for equal error | brightness, BSDF alone / map sampled |\n");
        std::printf("|---|---|---|---|---|---|\n");
        std::vector<double> sampledErrors, escapingErrors;
        for (int spp : counts) {
            const io::Image a = renderScene(sampled, width, height, spp, 2).image;
            const io::Image b = renderScene(escaping, width, height, spp, 2).image;
            sampledErrors.push_back(relativeRmse(a, reference));
            escapingErrors.push_back(relativeRmse(b, reference));
            const double ratio = escapingErrors.back() / sampledErrors.back();
            std::printf("| %d | %.4g | %.4g | %.2fx | %.0fx | %.4f |\n", spp, sampledErrors.back(),
                        escapingErrors.back(), ratio, ratio * ratio, brightness(b) / brightness(a));
            std::fflush(stdout);
        }
        // BSDF sampling's spp for the map sampled's error at the smallest count, on the
        // log-log line through the two counts that bracket it (or the last two).
        const double target = sampledErrors.front();
        std::size_t k = 1;
        while (k + 1 < counts.size() && escapingErrors[k] > target)
            ++k;
        const double slope = std::log(escapingErrors[k] / escapingErrors[k - 1]) /
                             std::log(static_cast<double>(counts[k]) / counts[k - 1]);
        const double needed =
            counts[k - 1] * std::exp(std::log(target / escapingErrors[k - 1]) / slope);
        std::printf("\nEqual error: the map sampled reaches rel RMSE %.4g at %d spp; BSDF "
                    "sampling alone reaches it at about %.0f spp (log-log slope %.2f between %d "
                    "and %d spp): %.0fx the samples.\n",
                    target, counts.front(), needed, slope, counts[k - 1], counts[k],
                    needed / counts.front());

        std::vector<double> sampledTimes, escapingTimes;
        for (int round = 0; round < rounds; ++round) {
            sampledTimes.push_back(
                renderScene(sampled, width, height, timingSamples, 3).secondsPerSample);
            escapingTimes.push_back(
                renderScene(escaping, width, height, timingSamples, 3).secondsPerSample);
        }
        const double pixels = static_cast<double>(width) * height;
        const double a = median(sampledTimes), b = median(escapingTimes);
        std::printf("\n| | map sampled (MIS) | BSDF sampling alone | ratio |\n|---|---|---|---|\n");
        std::printf("| time per sample (ms, %dx%d) | %.3f | %.3f | %.2fx |\n", width, height,
                    1e3 * a, 1e3 * b, a / b);
        std::printf("| Mpaths/s | %.3f | %.3f | |\n", pixels / a * 1e-6, pixels / b * 1e-6);
        std::printf("(median of %d alternating rounds of %d spp)\n", rounds, timingSamples);
        const double equalTime = (escapingErrors.front() / sampledErrors.front()) *
                                 (escapingErrors.front() / sampledErrors.front()) * b / a;
        std::printf("\nAt equal time (the error ratio squared, over the cost ratio): %.0fx fewer "
                    "seconds for the same error.\n",
                    equalTime);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "bench_environment_sampling: %s\n", error.what());
        return 1;
    }
    return 0;
}
