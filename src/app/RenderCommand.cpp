#include "app/RenderCommand.h"

#include "app/FramePacing.h"
#include "app/InteractiveSession.h"
#include "app/Interrupt.h"
#include "app/Progress.h"
#include "app/SceneLoading.h"
#include "io/ImageFile.h"
#include "io/OutputFiles.h"
#include "platform/ContextFactory.h"
#include "platform/GlfwWindowContext.h"
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
    std::vector<io::OutputImage> images = {{path, picture, attributes, {}}};
    if (line.statisticsOutput)
        images.push_back({*line.statisticsOutput, renderer.sampleStatistics(), attributes, {}});
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
    // Every texture must be readable before a window opens or a frame is rendered.
    const scene::Scene scene = loadScene(line.scene);
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
    render::RenderSettings settings = line.settings;
    // The window's panel switches the environment off without a recompile.
    settings.switchableEnvironment = context->hasWindow();
    render::ProgressiveRenderer renderer(scene, line.width, line.height, settings);
    const double setupSeconds = secondsSince(setupStart);

    bool endedEarly = false;
    double renderSeconds = 0.0;
    if (context->hasWindow()) {
        InteractiveSession session(static_cast<platform::GlfwWindowContext&>(*context), renderer,
                                   scene, line, interrupt);
        // A window closed before the end the command line set is an interrupted render.
        endedEarly = !session.run() && line.isBatch();
        renderSeconds = session.renderSeconds();
    } else {
        Progress progress(line.width, line.height, line.seconds, line.samplesPerPixel,
                          !line.quiet);
        const auto renderStart = std::chrono::steady_clock::now();
        auto keepGoing = [&] {
            return !interrupt.requested() &&
                   (!line.seconds || secondsSince(renderStart) < *line.seconds);
        };
        // Unless told, the samples per frame follow the measured cost (the first frame,
        // which includes code generation, is not a measure).
        int samplesPerFrame = line.settings.samplesPerFrame;
        while (keepGoing()) {
            if (line.samplesPerPixel && renderer.samplesPerPixel() >= *line.samplesPerPixel)
                break;
            int samples = samplesPerFrame;
            if (line.samplesPerPixel)
                samples = std::min(samples, *line.samplesPerPixel - renderer.samplesPerPixel());
            if (!renderer.renderFrame(keepGoing, samples))
                break;
            progress.update(renderer.samplesPerPixel());
            if (!line.samplesPerFrameGiven && renderer.frames() > 1)
                samplesPerFrame = samplesPerFrameFor(0.5, renderer.lastSecondsPerSample());
        }
        // Exactly --spp samples in every pixel, also where a frame's loop budget left one
        // short (ProgressiveRenderer::renderFrame).
        if (line.samplesPerPixel && renderer.samplesPerPixel() >= *line.samplesPerPixel &&
            !interrupt.requested())
            renderer.completeSamples();
        renderSeconds = secondsSince(renderStart);
        progress.finish();
    }
    // A render with an end (SECONDS or --spp) stopped before it by Ctrl-C or by closing its
    // window is interrupted; a window without an end is meant to be closed.
    const bool interrupted = interrupt.requested() || endedEarly;
    std::string summary = Progress::summary(renderer.width(), renderer.height(),
                                            renderer.samplesPerPixel(), renderSeconds,
                                            renderer.discardedSamples());
    char setup[64];
    std::snprintf(setup, sizeof setup, " (setup %.2f s)", setupSeconds);
    summary += setup;

    // An image without a sample is all black: never written, and never over an older file.
    if (writesFile && renderer.samplesPerPixel() == 0) {
        if (!interrupted) {
            char reason[160];
            std::snprintf(reason, sizeof reason,
                          "the render's %.3g s ended before its first sample was complete: "
                          "nothing written (give more SECONDS)",
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
            if (size.width == renderer.width() && size.height == renderer.height()) {
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
        summary += " -> " + line.outputPath().string();
        if (line.statisticsOutput)
            summary += " and " + line.statisticsOutput->string();
    }

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
        scene::dropInvisibleObjects(scene), render::shaderBuild(line.settings));
    std::cout << render::assemblePathTracerSource(code,
                                                  scene::FileLookup::dataDirectory() / "shaders")
                     .text();
    return kExitSuccess;
}

}  // namespace app
