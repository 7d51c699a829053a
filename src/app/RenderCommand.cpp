#include "app/RenderCommand.h"

#include "app/BuildInfo.h"
#include "app/ErrorTargetRun.h"
#include "interaction/FramePacing.h"
#include "app/InteractiveSession.h"
#include "app/Interrupt.h"
#include "app/Progress.h"
#include "app/RenderOutputs.h"
#include "app/SceneDigest.h"
#include "app/SceneLoading.h"
#include "io/ImageFile.h"
#include "io/OutputFiles.h"
#include "platform/ContextFactory.h"
#include "platform/GlfwWindowContext.h"
#include "render/ProgressiveRenderer.h"
#include "film/RenderFile.h"
#include "render/ScenePreparation.h"
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

// The render --resume goes on from, checked against the one the command line asks for:
// same size, scene, camera, image-changing settings and program build. `line` takes the
// file's size and seed where the command line gives none.
film::RenderFile readResumedRender(CommandLine& line, const scene::Scene& scene,
                                     const std::string& sceneSha256)
{
    const std::filesystem::path& path = *line.resume;
    film::RenderFile resumed;
    try {
        resumed = film::readRenderFile(path);
    } catch (const std::exception& error) {
        throw std::runtime_error(std::string("cannot resume: ") + error.what());
    }
    const film::RenderMetadata& held = resumed.metadata;
    if (!line.sizeGiven) {
        line.width = held.width;
        line.height = held.height;
    }
    if (!line.seedGiven && !held.sampleRanges.empty())
        line.settings.seed = held.sampleRanges.front().seed;

    film::RenderMetadata asked = held;
    asked.width = line.width;
    asked.height = line.height;
    asked.sceneSha256 = sceneSha256;
    asked.camera = scene.camera;
    asked.settings = line.settings;
    asked.program = programName();
    asked.gitCommit = gitCommit();
    if (const auto difference = film::imageDifference(held, asked))
        throw std::runtime_error("cannot resume " + path.string() + ": it differs from this "
                                 "render in " + difference->what + ": " + difference->first +
                                 " in the file, " + difference->second + " here");
    const film::SampleCountSpan span = film::samplesTakenSpan(resumed.accumulation);
    if (line.samplesPerPixel && span.fewest >= *line.samplesPerPixel)
        throw std::runtime_error(path.string() + " holds " + std::to_string(span.fewest) +
                                 " samples per pixel already: --spp " +
                                 std::to_string(*line.samplesPerPixel) +
                                 " adds none (--spp counts them all; give more, or SECONDS)");
    return resumed;
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

// Where adaptive sampling has left a few pixels sampling, a frame adds up to this many
// samples to each (below the shader's loop budget for most paths, constants.glsl).
constexpr int kMostAdaptiveSamplesPerFrame = 1024;

// What ended a render aimed at an error before it got there.
std::string targetStop(const CommandLine& line, const ErrorTargetRun& run, bool interrupted)
{
    if (interrupted)
        return "interrupted before it";
    if (run.limitReached() || (line.samplesPerPixel && !run.adaptive()))
        return "stopped at --spp " + std::to_string(*line.samplesPerPixel) + " before it";
    return "stopped at the time limit before it";
}

}  // namespace

int runRender(const CommandLine& commandLine)
{
    // From the start: Ctrl-C while the shader compiles must not kill the program unseen.
    InterruptWatch interrupt;
    CommandLine line = commandLine;
    if (line.statisticsOutput && io::resolveToSameFile(line.outputPath(), *line.statisticsOutput))
        throw UsageError("--stats-output " + line.statisticsOutput->string() + " names the same "
                         "file as the image, " + line.outputPath().string() +
                         ": give two different files");
    if (line.resume && line.statisticsOutput &&
        io::resolveToSameFile(*line.resume, *line.statisticsOutput))
        throw UsageError("--stats-output " + line.statisticsOutput->string() + " names the "
                         "render being resumed: give another file");
    // Every texture must be readable before a window opens or a frame is rendered.
    const scene::Scene scene = loadScene(line.scene);
    std::string sceneDigest = sceneSha256(filesOfScene(line.scene, scene));
    std::optional<film::RenderFile> resumed;
    if (line.resume)
        resumed = readResumedRender(line, scene, sceneDigest);
    const bool writesFile = line.isBatch() || line.output.has_value();
    if (writesFile)
        io::checkOutputsCanBeWritten(outputRequests(line));
    // A resumed render goes on where the file left it: no window, whose camera and settings
    // could leave that.
    const bool headless = line.headless || line.resume || !platform::displayAvailable();
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
    settings::RenderSettings settings = line.settings;
    // The window's panel switches the environment off without a recompile.
    settings.switchableEnvironment = context->hasWindow();
    render::ProgressiveRenderer renderer(scene, line.width, line.height, settings);
    // A window samples every pixel alike (InteractiveSession).
    std::optional<ErrorTargetRun> errorTarget;
    if (line.targetError)
        errorTarget.emplace(line.adaptiveSampling, !line.uniformSampling && !context->hasWindow());
    int samplesResumed = 0;
    int fewestResumed = 0;
    if (resumed) {
        renderer.resumeFrom(resumed->accumulation);
        samplesResumed = renderer.samplesPerPixel();
        fewestResumed = film::samplesTakenSpan(resumed->accumulation).fewest;
    }
    const double setupSeconds = secondsSince(setupStart);

    bool endedEarly = false;
    double renderSeconds = 0.0;
    if (context->hasWindow()) {
        InteractiveSession session(static_cast<platform::GlfwWindowContext&>(*context), renderer,
                                   scene, line, interrupt);
        // A window closed before the end the command line set is an interrupted render.
        endedEarly = !session.run() && line.isBatch();
        renderSeconds = session.renderSeconds();
        // The scene may have been edited and reloaded in the window.
        sceneDigest = session.sceneSha256();
    } else {
        Progress progress(line.width, line.height, line.seconds, line.samplesPerPixel,
                          !line.quiet, samplesResumed);
        const auto renderStart = std::chrono::steady_clock::now();
        auto keepGoing = [&] {
            return !interrupt.requested() &&
                   (!line.seconds || secondsSince(renderStart) < *line.seconds);
        };
        if (errorTarget)
            errorTarget->start(renderer);
        interaction::SamplesPerFrame pacing(line.settings.samplesPerFrame, line.samplesPerFrameGiven, 0.5,
                               renderer.samplesAdaptively() ? kMostAdaptiveSamplesPerFrame : 16);
        while (keepGoing()) {
            if (errorTarget && (errorTarget->reached() || errorTarget->limitReached()))
                break;
            // Adaptive sampling limits each pixel to --spp itself (film/AdaptiveSampling.h).
            const bool countsUniformSamples = !errorTarget || !errorTarget->adaptive();
            if (countsUniformSamples && line.samplesPerPixel &&
                renderer.samplesPerPixel() >= *line.samplesPerPixel)
                break;
            int samples = pacing.samples();
            if (countsUniformSamples && line.samplesPerPixel)
                samples = std::min(samples, *line.samplesPerPixel - renderer.samplesPerPixel());
            if (!renderer.renderFrame(keepGoing, samples))
                break;
            if (errorTarget) {
                errorTarget->afterFrame(renderer, secondsSince(renderStart));
                progress.update(renderer.samplesPerPixel(), errorTarget->progressText());
            } else {
                progress.update(renderer.samplesPerPixel());
            }
            // Under adaptive sampling a frame lasts as long as its busiest pixels sample
            // (ErrorTargetRun::mostSamplesAddedToAPixel), and a pixel behind the frames' count
            // may take up to twice the samples asked (ProgressiveRenderer::drawFrame), as
            // most pixels are there: the frame's cost per sample asked is the cost of those
            // twice as many.
            double secondsPerSample = renderer.lastSecondsPerSample();
            if (errorTarget && errorTarget->adaptive() &&
                errorTarget->mostSamplesAddedToAPixel() > 0.0f)
                secondsPerSample *=
                    std::max(1.0, 2.0 * samples / errorTarget->mostSamplesAddedToAPixel());
            pacing.afterFrame(renderer.frames(), secondsPerSample,
                              errorTarget ? errorTarget->predictedSecondsLeft() : std::nullopt);
        }
        // Exactly --spp samples in every pixel, also where a frame's loop budget left one
        // short (ProgressiveRenderer::renderFrame), or an interrupted render resumed did.
        if (line.samplesPerPixel && renderer.samplesPerPixel() >= *line.samplesPerPixel &&
            !interrupt.requested() && !renderer.samplesAdaptively() &&
            !(errorTarget && errorTarget->reached()))
            renderer.completeSamples();
        renderSeconds = secondsSince(renderStart);
        progress.finish();
    }
    // A render with an end (SECONDS or --spp) stopped before it by Ctrl-C or by closing its
    // window is interrupted; a window without an end is meant to be closed.
    const bool interrupted = interrupt.requested() || endedEarly;
    const film::Accumulation accumulation = renderer.accumulation();
    std::string summary =
        renderer.samplesAdaptively()
            ? Progress::adaptiveSummary(renderer.width(), renderer.height(),
                                        film::samplesTakenSpan(accumulation),
                                        film::samplesTakenInAll(accumulation), renderSeconds,
                                        renderer.discardedSamples())
            : Progress::summary(renderer.width(), renderer.height(), renderer.samplesPerPixel(),
                                renderSeconds, renderer.discardedSamples(), samplesResumed);
    char setup[64];
    std::snprintf(setup, sizeof setup, " (setup %.2f s)", setupSeconds);
    summary += setup;

    // An image without a sample is all black, and a resumed render without a new sample is
    // the file it resumed: neither is written, nor over an older file.
    const bool nothingNew =
        resumed ? film::samplesTakenInAll(accumulation) <=
                      film::samplesTakenInAll(resumed->accumulation)
                : renderer.samplesPerPixel() == 0;
    if (writesFile && nothingNew) {
        if (!interrupted) {
            char reason[160];
            std::snprintf(reason, sizeof reason,
                          "the render's %.3g s ended before its first %ssample was complete: "
                          "nothing written (give more SECONDS)",
                          renderSeconds, resumed ? "new " : "");
            throw std::runtime_error(reason);
        }
        std::error_code error;
        const bool older = std::filesystem::exists(line.outputPath(), error);
        std::cout << summary << " (interrupted before the first " << (resumed ? "new " : "")
                  << "sample: nothing written"
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
        film::RenderMetadata metadata = describeRender(line.scene, sceneDigest, renderer);
        metadata.renderSeconds = renderSeconds;
        if (resumed) {
            // The new samples of each pixel take the indices from its count on: from the
            // fewest any pixel held to the count all reach.
            std::vector<film::SampleRange> ranges = resumed->metadata.sampleRanges;
            ranges.push_back({line.settings.seed, fewestResumed,
                              renderer.samplesPerPixel() - fewestResumed});
            metadata.sampleRanges = film::normalizedRanges(ranges);
            metadata.renderSeconds += resumed->metadata.renderSeconds;
            metadata.mergedFrom = resumed->metadata.mergedFrom;
        }
        if (interrupted)
            metadata.interrupted =
                interruptionNote(line, renderer.samplesPerPixel(), renderSeconds);
        // Both images, or neither (io/OutputFiles.h).
        io::writeAllOrNothing(renderOutputs(
            {line.outputPath()}, line.statisticsOutput, accumulation, metadata,
            [&] { return fromWindow ? windowPicture : renderer.toneMapped(); }));
        summary += " -> " + line.outputPath().string();
        if (line.statisticsOutput)
            summary += " and " + line.statisticsOutput->string();
    }

    if (interrupted)
        summary += " (interrupted)";
    if (errorTarget) {
        errorTarget->conclude(renderer);
        summary += "; " + errorTarget->summaryText(targetStop(line, *errorTarget, interrupted));
    }
    std::cout << summary << std::endl;
    return interrupted ? kExitInterrupted : kExitSuccess;
}

int printFeatures(const CommandLine& line)
{
    const render::PreparedScene prepared =
        render::prepareScene(scene::parseSceneFile(line.scene),
                             shadergen::shaderBuild(line.settings), render::defaultShaderDirectory());
    std::cout << prepared.code.features.describe();
    return kExitSuccess;
}

int printShader(const CommandLine& line)
{
    const render::PreparedScene prepared =
        render::prepareScene(scene::parseSceneFile(line.scene),
                             shadergen::shaderBuild(line.settings), render::defaultShaderDirectory());
    std::cout << prepared.fragmentSource.text();
    return kExitSuccess;
}

}  // namespace app
