#include "app/RenderCommand.h"

#include "app/FramePacing.h"
#include "app/InteractiveSession.h"
#include "app/Interrupt.h"
#include "app/Progress.h"
#include "app/SceneLoading.h"
#include "io/ImageFile.h"
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

void writeOutputs(const CommandLine& line, const render::ProgressiveRenderer& renderer,
                  const io::Image* windowPicture)
{
    const std::filesystem::path path = line.outputPath();
    if (io::holdsLinearRadiance(path))
        io::writeImage(path, renderer.radiance());
    else
        io::writeImage(path, windowPicture != nullptr ? *windowPicture : renderer.toneMapped());
    if (line.statisticsOutput)
        io::writeImage(*line.statisticsOutput, renderer.sampleStatistics());
}

}  // namespace

int runRender(const CommandLine& line)
{
    // From the start: Ctrl-C while the shader compiles must not kill the program unseen.
    InterruptWatch interrupt;
    // Every texture must be readable before a window opens or a frame is rendered.
    const scene::Scene scene = loadScene(line.scene);
    const bool writesFile = line.isBatch() || line.output.has_value();
    if (writesFile) {
        io::checkWritableFormat(line.outputPath());
        if (line.statisticsOutput)
            io::checkWritableFormat(*line.statisticsOutput);
    }
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
    const bool interrupted = interrupt.requested() || endedEarly;

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
        writeOutputs(line, renderer, fromWindow ? &windowPicture : nullptr);
    }

    std::string summary = Progress::summary(renderer.width(), renderer.height(),
                                            renderer.samplesPerPixel(), renderSeconds,
                                            renderer.discardedSamples());
    char setup[64];
    std::snprintf(setup, sizeof setup, " (setup %.2f s)", setupSeconds);
    summary += setup;
    if (writesFile)
        summary += " -> " + line.outputPath().string();
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
        scene::dropInvisibleObjects(scene), line.settings.variant,
        render::EnvironmentBinding::BuiltIn, line.settings.exactGeometry);
    std::cout << render::assemblePathTracerSource(code,
                                                  scene::FileLookup::dataDirectory() / "shaders")
                     .text();
    return kExitSuccess;
}

}  // namespace app
