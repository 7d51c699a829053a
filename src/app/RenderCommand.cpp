#include "app/RenderCommand.h"

#include "app/Interrupt.h"
#include "app/Progress.h"
#include "io/ImageFile.h"
#include "io/OutputFiles.h"
#include "platform/ContextFactory.h"
#include "render/PathTracerProgram.h"
#include "render/ProgressiveRenderer.h"
#include "scene/FileLookup.h"
#include "scene/InvisibleObjects.h"
#include "scene/SceneFeatures.h"
#include "scene/SceneParser.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>

namespace app {

namespace {

double secondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string windowTitle(const CommandLine& line, int samples, double rate)
{
    char text[256];
    std::snprintf(text, sizeof text, "raytracer - %s - %d spp, %.2f spp/s",
                  line.scene.filename().string().c_str(), samples, rate);
    return text;
}

// The files the run will write, checked before the scene is rendered.
std::vector<io::OutputRequest> outputRequests(const CommandLine& line)
{
    std::vector<io::OutputRequest> outputs = {{line.outputPath(), io::OutputKind::Image}};
    if (line.statisticsOutput)
        outputs.push_back({*line.statisticsOutput, io::OutputKind::Statistics});
    return outputs;
}

// Both images, or neither (io/OutputFiles.h).
void writeOutputs(const CommandLine& line, const render::ProgressiveRenderer& renderer,
                  const io::Image* windowPicture,
                  const std::vector<io::ImageAttribute>& attributes)
{
    const std::filesystem::path path = line.outputPath();
    const io::Image picture = io::holdsLinearRadiance(path) ? renderer.radiance()
                              : windowPicture != nullptr   ? *windowPicture
                                                           : renderer.toneMapped();
    std::vector<io::OutputImage> images = {{path, &picture, attributes}};
    io::Image statistics;
    if (line.statisticsOutput) {
        statistics = renderer.sampleStatistics();
        images.push_back({*line.statisticsOutput, &statistics, attributes});
    }
    io::writeAllOrNothing(images);
}

// What an interrupted file says of itself (attribute raytracer:interrupted).
std::string interruptionNote(const CommandLine& line, int samples, double seconds)
{
    char text[160];
    if (line.samplesPerPixel)
        std::snprintf(text, sizeof text, "stopped at %d of %d samples per pixel", samples,
                      *line.samplesPerPixel);
    else if (line.seconds)
        std::snprintf(text, sizeof text,
                      "stopped after %.2f of %g seconds, at %d samples per pixel", seconds,
                      *line.seconds, samples);
    else
        std::snprintf(text, sizeof text, "stopped at %d samples per pixel", samples);
    return text;
}

}  // namespace

int runRender(const CommandLine& line)
{
    // From the start: Ctrl-C while the shader compiles must not kill the program unseen.
    InterruptWatch interrupt;
    if (line.statisticsOutput && io::resolveToSameFile(line.outputPath(), *line.statisticsOutput))
        throw UsageError("--stats-output " + line.statisticsOutput->string() + " names the same "
                         "file as the image, " + line.outputPath().string() +
                         ": give two different files");
    const scene::Scene scene = scene::parseSceneFile(line.scene);
    // Every texture must be readable before a window opens or a frame is rendered.
    for (const scene::Pigment& pigment : scene.pigments)
        if (pigment.kind == scene::PigmentKind::Texture) {
            try {
                io::checkReadableImage(pigment.texturePath);
            } catch (const std::exception& error) {
                throw std::runtime_error(line.scene.string() + ":" +
                                         std::to_string(pigment.line) + ": texture '" +
                                         pigment.textureName + "': " + error.what());
            }
        }
    const bool writesFile = line.isBatch() || line.output.has_value();
    if (writesFile)
        io::checkOutputsCanBeWritten(outputRequests(line));
    const bool headless = line.headless || !platform::displayAvailable();
    if (headless && !line.isBatch())
        throw UsageError(std::string(line.headless ? "--headless" : "there is no display, so") +
                         " renders need an end: give SECONDS or --spp (the image is written "
                         "to a file)");

    platform::ContextRequest request;
    request.headless = headless;
    request.windowWidth = line.width;
    request.windowHeight = line.height;
    request.windowTitle = "raytracer - " + line.scene.filename().string();
    const auto setupStart = std::chrono::steady_clock::now();
    auto context = platform::createContext(request);
    render::ProgressiveRenderer renderer(scene, line.width, line.height, line.settings);
    const double setupSeconds = secondsSince(setupStart);

    Progress progress(line.width, line.height, line.seconds, line.samplesPerPixel,
                      line.isBatch() && !line.quiet);
    const auto renderStart = std::chrono::steady_clock::now();
    bool windowClosed = false;
    auto timeLeft = [&] { return !line.seconds || secondsSince(renderStart) < *line.seconds; };
    auto keepGoing = [&] {
        if (context->hasWindow() && context->closeRequested())
            windowClosed = true;
        return !interrupt.requested() && !windowClosed && timeLeft();
    };

    // Several paths per pixel per frame keep SIMD lanes busy (a pixel whose path ends starts
    // the next at once) and the per-draw overhead small; a window still wants frequent
    // frames. Unless told, the count follows the measured cost (the first frame, which
    // includes code generation, is not a measure).
    const double targetFrameSeconds = context->hasWindow() && !line.isBatch() ? 0.15 : 0.5;
    int samplesPerFrame = line.settings.samplesPerFrame;
    auto lastTitle = std::chrono::steady_clock::now();
    while (keepGoing()) {
        if (line.samplesPerPixel && renderer.samplesPerPixel() >= *line.samplesPerPixel)
            break;
        int samples = samplesPerFrame;
        if (line.samplesPerPixel)
            samples = std::min(samples, *line.samplesPerPixel - renderer.samplesPerPixel());
        if (!renderer.renderFrame(keepGoing, samples))
            break;
        progress.update(renderer.samplesPerPixel());
        if (!line.samplesPerFrameGiven && renderer.frames() > 1 &&
            renderer.lastSecondsPerSample() > 0.0)
            samplesPerFrame = std::clamp(
                static_cast<int>(targetFrameSeconds / renderer.lastSecondsPerSample()), 1, 16);
        if (context->hasWindow()) {
            const platform::DrawableSize size = context->windowFramebufferSize();
            renderer.displayToWindow(size.width, size.height);
            context->present();
            if (secondsSince(lastTitle) > 0.25) {
                const double elapsed = secondsSince(renderStart);
                context->setTitle(windowTitle(line, renderer.samplesPerPixel(),
                                              renderer.samplesPerPixel() / elapsed));
                lastTitle = std::chrono::steady_clock::now();
            }
        }
    }
    const double renderSeconds = secondsSince(renderStart);
    progress.finish();

    // A render with an end (SECONDS or --spp) stopped before it by Ctrl-C or by closing its
    // window is interrupted; a window without an end is meant to be closed.
    const bool endReached =
        (line.samplesPerPixel && renderer.samplesPerPixel() >= *line.samplesPerPixel) ||
        (line.seconds && renderSeconds >= *line.seconds);
    const bool interrupted =
        interrupt.requested() || (line.isBatch() && windowClosed && !endReached);
    std::string summary = Progress::summary(line.width, line.height, renderer.samplesPerPixel(),
                                            renderSeconds, renderer.discardedSamples());
    char setup[64];
    std::snprintf(setup, sizeof setup, " (setup %.2f s)", setupSeconds);
    summary += setup;

    // An image without a sample is all black: never written, and never over an older file.
    if (writesFile && renderer.samplesPerPixel() == 0) {
        if (!interrupted) {
            char reason[160];
            std::snprintf(reason, sizeof reason,
                          windowClosed ? "the window was closed before the first sample was "
                                         "complete: nothing written"
                                       : "the render's %.3g s ended before its first sample "
                                         "was complete: nothing written (give more SECONDS)",
                          renderSeconds);
            throw std::runtime_error(reason);
        }
        std::error_code error;
        const bool older = std::filesystem::exists(line.outputPath(), error);
        std::cout << summary << " (interrupted before the first sample: nothing written"
                  << (older ? ", " + line.outputPath().string() + " left as it was" : "")
                  << ")" << std::endl;
        return kExitInterrupted;
    }

    if (writesFile) {
        io::Image windowPicture;
        bool fromWindow = false;
        if (context->hasWindow()) {
            // The picture the window shows is the one written: draw it once more and read it
            // back before it is presented.
            const platform::DrawableSize size = context->windowFramebufferSize();
            if (size.width == line.width && size.height == line.height) {
                renderer.displayToWindow(size.width, size.height);
                windowPicture = render::readWindowPixels(size.width, size.height);
                fromWindow = true;
            }
        }
        std::vector<io::ImageAttribute> attributes;
        if (interrupted)
            attributes.push_back({"raytracer:interrupted",
                                  interruptionNote(line, renderer.samplesPerPixel(),
                                                   renderSeconds)});
        writeOutputs(line, renderer, fromWindow ? &windowPicture : nullptr, attributes);
    }

    if (writesFile)
        summary += " -> " + line.outputPath().string();
    if (writesFile && line.statisticsOutput)
        summary += " and " + line.statisticsOutput->string();
    if (interrupted)
        summary += " (interrupted)";
    std::cout << summary << std::endl;
    return interrupted ? kExitInterrupted : kExitSuccess;
}

int printFeatures(const CommandLine& line)
{
    const scene::Scene scene = scene::parseSceneFile(line.scene);
    std::cout << scene::analyseFeatures(scene).describe();
    return kExitSuccess;
}

int printShader(const CommandLine& line)
{
    const scene::Scene scene = scene::parseSceneFile(line.scene);
    const render::SceneShaderCode code = render::generateSceneShaderCode(
        scene::dropInvisibleObjects(scene), line.settings.variant);
    std::cout << render::assemblePathTracerSource(code,
                                                  scene::FileLookup::dataDirectory() / "shaders")
                     .text();
    return kExitSuccess;
}

}  // namespace app
