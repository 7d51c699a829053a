#include "app/RenderCommand.h"
#include "app/Denoising.h"
#include "film/Denoiser.h"

#include "app/BuildInfo.h"
#include "app/ErrorTargetRun.h"
#include "app/InteractiveSession.h"
#include "app/Interrupt.h"
#include "app/Progress.h"
#include "app/RenderOutputs.h"
#include "app/SceneDigest.h"
#include "app/SceneLoading.h"
#include "film/RenderFile.h"
#include "interaction/FramePacing.h"
#include "io/ImageFile.h"
#include "io/OutputFiles.h"
#include "platform/ContextFactory.h"
#include "platform/GlfwWindowContext.h"
#include "render/KernelChoice.h"
#include "render/ProgressiveRenderer.h"
#include "render/ScenePreparation.h"
#include "scene/Lights.h"
#include "scene/SceneFeatures.h"
#include "scene/SceneParser.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>

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
    if (line.denoise)
        outputs.push_back({denoisedPath(line.outputPath()), io::OutputKind::Image});
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
    if (held.crop)
        throw std::runtime_error("cannot resume " + path.string() + ": it holds the crop " +
                                 film::formatCrop(*held.crop) +
                                 " of its frame only (--crop); "
                                 "render more of the crop with another --seed and merge");
    if (!line.sizeGiven) {
        line.width = held.width;
        line.height = held.height;
    }
    if (!line.given("--seed") && !held.sampleRanges.empty())
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
        throw std::runtime_error("cannot resume " + path.string() +
                                 ": it differs from this "
                                 "render in " +
                                 difference->what + ": " + difference->first + " in the file, " +
                                 difference->second + " here");
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

// A batch render's frames aim at this long. Neighbouring pixels run in lockstep on SIMD
// hardware, and a frame ends for a group of them when its slowest pixel has traced its
// paths: the more paths a frame gives each pixel, the less of that wait there is per path
// (scene 6 of the original at 400x300, 24 spp: 0.87 Mpaths/s with 0.5 s frames, of about 4
// paths, 0.97 with frames of 8 paths or more). What a longer frame costs: an interrupt,
// still honoured between bands (ProgressiveRenderer::drawFrame), drops the frame it cuts,
// now up to 2 s of work; frames aim to end by a time limit (interaction::SamplesPerFrame),
// so the limit drops none.
constexpr double kBatchFrameSeconds = 2.0;

// What ended a render aimed at an error before it got there.
std::string targetStop(const CommandLine& line, const ErrorTargetRun& run, bool interrupted)
{
    if (interrupted)
        return "interrupted before it";
    if (run.limitReached() || (line.samplesPerPixel && !run.adaptive()))
        return "stopped at --spp " + std::to_string(*line.samplesPerPixel) + " before it";
    return "stopped at the time limit before it";
}

// Everything a render needs before its first frame, made in this order: the context before
// the renderer, which draws in it (and is destroyed before it).
struct RenderSetup {
    scene::Scene scene;
    std::string sceneDigest;  // of the scene's files (SceneDigest.h)
    std::optional<film::RenderFile> resumed;
    bool writesFile = false;
    std::unique_ptr<platform::GlContext> context;
    std::unique_ptr<render::ProgressiveRenderer> renderer;
    std::optional<ErrorTargetRun> errorTarget;
    int samplesResumed = 0;  // samples per pixel of the file resumed
    int fewestResumed = 0;   // the fewest any of its pixels holds
    double setupSeconds = 0.0;
    std::optional<film::PixelCrop> crop;  // --crop
};

// How the render went: stopped before the end the command line set (its window closed), and
// for how long it rendered.
struct RenderRun {
    bool endedEarly = false;
    double seconds = 0.0;                 // of the accumulation the outputs hold
    std::optional<double> windowSeconds;  // the time the window was open, where there was one
};

}  // namespace

void removeStaleTemporariesOf(const std::vector<std::filesystem::path>& outputs, bool quiet)
{
    for (const io::StaleTemporary& removed : io::removeStaleTemporaries(outputs))
        if (!quiet)
            std::cout << "removed " << removed.path.string()
                      << ", a temporary file left by process " << removed.processId
                      << ", which no longer runs" << std::endl;
}

platform::ContextRequest contextRequest(const CommandLine& line)
{
    platform::ContextRequest request;
    request.kind = line.gl;
    request.headless = line.headless;
    request.gpuIndex = line.glDevice;
    request.windowWidth = line.width;
    request.windowHeight = line.height;
    request.windowTitle = "raytracer - " + line.scene.filename().string();
    return request;
}

std::string describeRenderingDevice(const platform::ContextIdentity& gl,
                                    const render::KernelChoice& kernel)
{
    return gl.describe() + ", " + settings::pathKernelName(kernel.kernel) + " kernel";
}

namespace {

// The output names make sense together: the statistics are neither the image nor the file
// resumed.
void checkOutputNames(const CommandLine& line)
{
    if (line.statisticsOutput && io::resolveToSameFile(line.outputPath(), *line.statisticsOutput))
        throw UsageError("--stats-output " + line.statisticsOutput->string() +
                         " names the same "
                         "file as the image, " +
                         line.outputPath().string() + ": give two different files");
    if (line.summaryJson && (io::resolveToSameFile(line.outputPath(), *line.summaryJson) ||
                             (line.statisticsOutput &&
                              io::resolveToSameFile(*line.statisticsOutput, *line.summaryJson))))
        throw UsageError("--summary-json " + line.summaryJson->string() +
                         " names a file the "
                         "render writes its image or statistics to: give another file");
    if (line.resume && line.statisticsOutput &&
        io::resolveToSameFile(*line.resume, *line.statisticsOutput))
        throw UsageError("--stats-output " + line.statisticsOutput->string() +
                         " names the "
                         "render being resumed: give another file");
}

// A scene that gives no light renders black: said on standard error before any time is
// spent, and refused with --strict.
void warnOfADarkScene(const CommandLine& line, const scene::Scene& scene)
{
    if (scene::emitsLight(scene))
        return;
    const std::string why = line.scene.string() +
                            " can emit no light (no light that is not "
                            "black, no emitting sphere, environment none): its image is black";
    if (line.strict)
        throw std::runtime_error(why + " (--strict)");
    std::cerr << "raytracer: warning: " << why << std::endl;
}

// Loads the scene and the render resumed, checks the outputs can be written, makes the
// context and the renderer. `line` takes a resumed file's size and seed where it gives none.
RenderSetup prepareRender(CommandLine& line)
{
    checkOutputNames(line);
    RenderSetup setup;
    // Every texture must be readable before a window opens or a frame is rendered.
    setup.scene = loadScene(line.scene);
    if (line.camera)
        setup.scene.camera = *line.camera;
    warnOfADarkScene(line, setup.scene);
    setup.sceneDigest = sceneSha256(filesOfScene(line.scene, setup.scene));
    if (line.resume)
        setup.resumed = readResumedRender(line, setup.scene, setup.sceneDigest);
    // --denoise needs the features; a resumed render keeps the ones its file holds.
    if (line.denoise || (setup.resumed && setup.resumed->accumulation.hasFeatures()))
        line.settings.featureBuffers = true;
    if (line.denoise)
        film::denoiserLibrary();  // found before anything is rendered, or a clear error
    setup.writesFile = line.isBatch() || line.output.has_value();
    if (setup.writesFile) {
        io::checkOutputsCanBeWritten(outputRequests(line));
        std::vector<std::filesystem::path> outputs = {line.outputPath()};
        if (line.statisticsOutput)
            outputs.push_back(*line.statisticsOutput);
        if (line.denoise)
            outputs.push_back(denoisedPath(line.outputPath()));
        removeStaleTemporariesOf(outputs, line.quiet);
    }
    // A resumed render goes on where the file left it: no window, whose camera and settings
    // could leave that.
    platform::ContextRequest request = contextRequest(line);
    request.headless = line.headless || line.resume || line.crop;
    if (platform::makesHeadlessContext(request) && !line.isBatch())
        throw UsageError(std::string(line.headless ? "--headless"
                                     : line.gl != platform::ContextKind::Automatic
                                         ? "--gl " + std::string(platform::contextKindName(line.gl))
                                         : "there is no display, so") +
                         " renders need an end: give SECONDS or --spp (the image is written "
                         "to a file)");

    const auto setupStart = std::chrono::steady_clock::now();
    setup.context = platform::createContext(request);
    settings::RenderSettings settings = line.settings;
    // The window's panel switches the environment off without a recompile.
    settings.switchableEnvironment = setup.context->hasWindow();
    // The window's preview denoiser is guided by the feature buffers.
    if (setup.context->hasWindow())
        settings.featureBuffers = true;
    setup.renderer = std::make_unique<render::ProgressiveRenderer>(setup.scene, line.width,
                                                                   line.height, settings);
    // A window samples every pixel alike (InteractiveSession).
    if (line.targetError)
        setup.errorTarget.emplace(line.adaptiveSampling,
                                  !line.uniformSampling && !setup.context->hasWindow());
    if (line.crop)
        setup.renderer->setCrop(line.crop->x0, line.crop->y0, line.crop->x1, line.crop->y1);
    if (setup.resumed) {
        setup.renderer->resumeFrom(setup.resumed->accumulation);
        setup.samplesResumed = setup.renderer->samplesPerPixel();
        setup.fewestResumed = film::samplesTakenSpan(setup.resumed->accumulation).fewest;
    }
    setup.crop = line.crop;
    setup.setupSeconds = secondsSince(setupStart);
    return setup;
}

// The window: until it is closed or the command line's end is reached. The scene may be
// edited and reloaded meanwhile: its digest is the one shown last.
RenderRun runInWindow(RenderSetup& setup, const CommandLine& line, const InterruptWatch& interrupt)
{
    InteractiveSession session(static_cast<platform::GlfwWindowContext&>(*setup.context),
                               *setup.renderer, setup.scene, line, interrupt);
    RenderRun run;
    // A window closed before the end the command line set is an interrupted render.
    run.endedEarly = !session.run() && line.isBatch();
    run.seconds = session.accumulationSeconds();
    run.windowSeconds = session.windowSeconds();
    setup.sceneDigest = session.sceneSha256();
    return run;
}

// Headless: frames until SECONDS, --spp, the target error or Ctrl-C, then exactly --spp
// samples in every pixel where that was the end.
RenderRun runBatch(RenderSetup& setup, const CommandLine& line, const InterruptWatch& interrupt)
{
    render::ProgressiveRenderer& renderer = *setup.renderer;
    std::optional<ErrorTargetRun>& errorTarget = setup.errorTarget;
    Progress progress(line.width, line.height, line.seconds, line.samplesPerPixel, !line.quiet,
                      setup.samplesResumed);
    const auto renderStart = std::chrono::steady_clock::now();
    auto keepGoing = [&] {
        return !interrupt.requested() &&
               (!line.seconds || secondsSince(renderStart) < *line.seconds);
    };
    if (errorTarget)
        errorTarget->start(renderer);
    interaction::SamplesPerFrame pacing(
        line.settings.samplesPerFrame, line.given("--samples-per-frame"), kBatchFrameSeconds,
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
        std::optional<double> secondsToLimit;
        if (line.seconds)
            secondsToLimit = *line.seconds - secondsSince(renderStart);
        pacing.afterFrame(renderer.frames(), secondsPerSample,
                          errorTarget ? errorTarget->predictedSecondsLeft() : std::nullopt,
                          secondsToLimit);
    }
    // Exactly --spp samples in every pixel, also where a frame's loop budget left one
    // short (ProgressiveRenderer::renderFrame), or an interrupted render resumed did.
    if (line.samplesPerPixel && renderer.samplesPerPixel() >= *line.samplesPerPixel &&
        !interrupt.requested() && !renderer.samplesAdaptively() &&
        !(errorTarget && errorTarget->reached()))
        renderer.completeSamples();
    RenderRun run;
    run.seconds = secondsSince(renderStart);
    progress.finish();
    return run;
}

// "64x48, 8 spp in 0.07 s: ... (setup 0.45 s)"
std::string summaryLine(const RenderSetup& setup, const film::Accumulation& accumulation,
                        const RenderRun& run)
{
    const render::ProgressiveRenderer& renderer = *setup.renderer;
    std::string summary =
        renderer.samplesAdaptively()
            ? Progress::adaptiveSummary(
                  renderer.width(), renderer.height(), film::samplesTakenSpan(accumulation),
                  film::samplesTakenInAll(accumulation), run.seconds, renderer.discardedSamples())
            : Progress::summary(renderer.width(), renderer.height(), renderer.samplesPerPixel(),
                                run.seconds, renderer.discardedSamples(), setup.samplesResumed);
    if (const auto& crop = setup.crop) {
        // The numbers are the crop's: the paths traced.
        summary = Progress::summary(crop->width(), crop->height(), renderer.samplesPerPixel(),
                                    run.seconds, renderer.discardedSamples(), 0) +
                  " (crop " + film::formatCrop(*crop) + " of " + std::to_string(renderer.width()) +
                  "x" + std::to_string(renderer.height()) + ")";
    }
    // Of the set-up, what building the hierarchy over the objects took, and what the scene's
    // data takes on the GPU (render/SceneDataBuffers.h), where the scene is read as data.
    std::string hierarchyText;
    if (renderer.sceneDataBytes() > 0) {
        char text[96];
        std::snprintf(text, sizeof text, ", hierarchy %.3f s, scene data %.2f MB",
                      renderer.hierarchySeconds(), renderer.sceneDataBytes() / 1e6);
        hierarchyText = text;
    }
    char setupText[192];
    if (run.windowSeconds)
        std::snprintf(setupText, sizeof setupText, " (setup %.2f s%s; window open %.2f s)",
                      setup.setupSeconds, hierarchyText.c_str(), *run.windowSeconds);
    else
        std::snprintf(setupText, sizeof setupText, " (setup %.2f s%s)", setup.setupSeconds,
                      hierarchyText.c_str());
    return summary + setupText + " [" +
           describeRenderingDevice(setup.context->identity(), renderer.kernel()) + "]";
}

// The picture and the statistics, with what the files say of themselves. The window's
// picture is the one on screen, drawn once more and read back.
void writeOutputs(RenderSetup& setup, const CommandLine& line,
                  const film::Accumulation& accumulation, const RenderRun& run, bool interrupted,
                  double& denoiseSeconds)
{
    render::ProgressiveRenderer& renderer = *setup.renderer;
    io::Image windowPicture;
    bool fromWindow = false;
    if (setup.context->hasWindow()) {
        const platform::DrawableSize size = setup.context->windowFramebufferSize();
        if (size.width == renderer.width() && size.height == renderer.height()) {
            renderer.displayToWindow(size.width, size.height);
            windowPicture = render::readWindowPixels(size.width, size.height);
            fromWindow = true;
        }
    }
    film::RenderMetadata metadata =
        describeRender(line.scene, setup.sceneDigest, renderer, setup.context->identity());
    metadata.renderSeconds = run.seconds;
    if (setup.resumed) {
        // The new samples of each pixel take the indices from its count on: from the
        // fewest any pixel held to the most any holds now (describeRender's count: under
        // adaptive sampling a pixel may hold more than the frames' count).
        std::vector<film::SampleRange> ranges = setup.resumed->metadata.sampleRanges;
        ranges.push_back({line.settings.seed, setup.fewestResumed,
                          metadata.samplesPerPixel - setup.fewestResumed});
        metadata.sampleRanges = film::normalizedRanges(ranges);
        metadata.renderSeconds += setup.resumed->metadata.renderSeconds;
        metadata.mergedFrom = setup.resumed->metadata.mergedFrom;
        // The samples held came from the resumed file's device, the new ones from this.
        film::RenderMetadata devices = setup.resumed->metadata;
        film::addRenderingDevice(devices, metadata);
        metadata.glContext = devices.glContext;
        metadata.glRenderer = devices.glRenderer;
        metadata.glVersion = devices.glVersion;
        metadata.kernel = devices.kernel;
    }
    if (interrupted)
        metadata.interrupted = interruptionNote(line, renderer.samplesPerPixel(), run.seconds);
    metadata.crop = line.crop;
    // All images, or none (io/OutputFiles.h).
    std::vector<io::OutputImage> outputs =
        renderOutputs({line.outputPath()}, line.statisticsOutput, accumulation, metadata,
                      [&] { return fromWindow ? windowPicture : renderer.toneMapped(); });
    if (line.denoise) {
        const auto start = std::chrono::steady_clock::now();
        outputs.push_back(denoisedOutput(denoisedPath(line.outputPath()),
                                         denoisedRadiance(accumulation), metadata,
                                         line.outputPath()));
        denoiseSeconds = secondsSince(start);
    }
    io::writeAllOrNothing(outputs);
}

// How a render ended, for the summary, --summary-json and the exit status.
struct RenderEnd {
    std::string stopReason;  // "samples", "time limit", "target error", ...
    std::optional<bool> targetReached;
    int exitStatus = kExitSuccess;
};

RenderEnd renderEnd(const RenderSetup& setup, const CommandLine& line, const RenderRun& run,
                    bool interrupted)
{
    RenderEnd end;
    if (setup.errorTarget)
        end.targetReached = setup.errorTarget->reached();
    if (interrupted) {
        end.stopReason = run.endedEarly ? "window closed" : "interrupted";
        end.exitStatus = kExitInterrupted;
        return end;
    }
    if (!line.isBatch()) {
        end.stopReason = "window closed";
        return end;
    }
    const render::ProgressiveRenderer& renderer = *setup.renderer;
    if (setup.errorTarget && setup.errorTarget->reached()) {
        end.stopReason = "target error";
    } else if ((setup.errorTarget && setup.errorTarget->limitReached()) ||
               (line.samplesPerPixel && renderer.samplesPerPixel() >= *line.samplesPerPixel)) {
        end.stopReason = "samples";
    } else {
        end.stopReason = "time limit";
    }
    if (setup.errorTarget && !setup.errorTarget->reached())
        end.exitStatus = kExitTargetNotReached;
    return end;
}

// `text` as a JSON string.
std::string jsonString(const std::string& text)
{
    std::string quoted = "\"";
    for (const char c : text) {
        if (c == '"' || c == '\\') {
            quoted += '\\';
            quoted += c;
        } else if (static_cast<unsigned char>(c) < 0x20) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
            quoted += escaped;
        } else {
            quoted += c;
        }
    }
    return quoted + "\"";
}

std::string jsonNumber(double value)
{
    if (!std::isfinite(value))
        return "null";
    char text[40];
    std::snprintf(text, sizeof text, "%.9g", value);
    return text;
}

// The summary's numbers as one JSON object (--summary-json; README, docs/USAGE.md).
std::string summaryJson(const RenderSetup& setup, const CommandLine& line,
                        const film::Accumulation& accumulation, const RenderRun& run,
                        const RenderEnd& end, const std::vector<std::filesystem::path>& written)
{
    const render::ProgressiveRenderer& renderer = *setup.renderer;
    const film::SampleCountSpan span = film::samplesTakenSpan(accumulation);
    const double samplesInAll = film::samplesTakenInAll(accumulation);
    const double resumedInAll =
        setup.resumed ? film::samplesTakenInAll(setup.resumed->accumulation) : 0.0;
    // As the summary line counts them: the paths this run traced.
    const double paths =
        renderer.samplesAdaptively()
            ? samplesInAll - resumedInAll
            : (setup.crop ? static_cast<double>(setup.crop->width()) * setup.crop->height()
                          : static_cast<double>(renderer.width()) * renderer.height()) *
                  (renderer.samplesPerPixel() - setup.samplesResumed);
    std::string text = "{\n";
    auto field = [&text](const char* name, const std::string& value) {
        text += std::string(text.size() > 2 ? ",\n" : "") + "  " + jsonString(name) + ": " + value;
    };
    field("scene", jsonString(line.scene.string()));
    field("width", std::to_string(renderer.width()));
    field("height", std::to_string(renderer.height()));
    field("crop", setup.crop ? jsonString(film::formatCrop(*setup.crop)) : "null");
    field("samplesPerPixel", std::to_string(renderer.samplesPerPixel()));
    field("fewestSamples", std::to_string(span.fewest));
    field("mostSamples", std::to_string(span.most));
    field("samplesResumed", std::to_string(setup.samplesResumed));
    field("samplesDiscarded", std::to_string(renderer.discardedSamples()));
    field("seconds", jsonNumber(run.seconds));
    field("setupSeconds", jsonNumber(setup.setupSeconds));
    field("megapathsPerSecond", jsonNumber(run.seconds > 0.0 ? paths / run.seconds / 1e6 : 0.0));
    const film::ErrorEstimate* estimate = setup.errorTarget && setup.errorTarget->estimate()
                                              ? &*setup.errorTarget->estimate()
                                              : nullptr;
    field("targetError", line.targetError ? jsonNumber(*line.targetError) : "null");
    field("errorReached", estimate ? jsonNumber(estimate->relativeError) : "null");
    field("errorUncertainty", estimate ? jsonNumber(estimate->uncertainty) : "null");
    field("targetReached",
          end.targetReached ? (*end.targetReached ? "true" : "false") : std::string("null"));
    field("stopReason", jsonString(end.stopReason));
    field("exitStatus", std::to_string(end.exitStatus));
    std::string outputs;
    for (const std::filesystem::path& path : written)
        outputs += (outputs.empty() ? "" : ", ") + jsonString(path.string());
    field("outputs", "[" + outputs + "]");
    field("device",
          jsonString(describeRenderingDevice(setup.context->identity(), renderer.kernel())));
    return text + "\n}\n";
}

void writeSummaryJson(const std::filesystem::path& path, const std::string& json)
{
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    file << json;
    file.close();
    if (!file)
        throw std::runtime_error("cannot write the summary to " + path.string());
}

// Writes what the render promised and prints its summary (unless --quiet) and writes it as
// JSON (--summary-json); returns the exit status.
int finishRender(RenderSetup& setup, const CommandLine& line, const RenderRun& run,
                 bool interrupted)
{
    render::ProgressiveRenderer& renderer = *setup.renderer;
    const film::Accumulation accumulation = renderer.accumulation();
    std::string summary = summaryLine(setup, accumulation, run);
    auto report = [&](const std::string& text, const RenderEnd& end,
                      const std::vector<std::filesystem::path>& written) {
        if (!line.quiet)
            std::cout << text << std::endl;
        if (line.summaryJson)
            writeSummaryJson(*line.summaryJson,
                             summaryJson(setup, line, accumulation, run, end, written));
    };

    // An image without a sample is all black, and a resumed render without a new sample is
    // the file it resumed: neither is written, nor over an older file.
    const bool nothingNew = setup.resumed ? film::samplesTakenInAll(accumulation) <=
                                                film::samplesTakenInAll(setup.resumed->accumulation)
                                          : renderer.samplesPerPixel() == 0;
    if (setup.writesFile && nothingNew) {
        const char* newSample = setup.resumed ? "new " : "";
        if (!interrupted) {
            char reason[160];
            std::snprintf(reason, sizeof reason,
                          "the render's %.3g s ended before its first %ssample was complete: "
                          "nothing written (give more SECONDS)",
                          run.seconds, newSample);
            throw std::runtime_error(reason);
        }
        std::error_code error;
        const bool older = std::filesystem::exists(line.outputPath(), error);
        report(summary + " (interrupted before the first " + newSample + "sample: nothing written" +
                   (older ? ", " + line.outputPath().string() + " left as it was" : "") + ")",
               renderEnd(setup, line, run, interrupted), {});
        return kExitInterrupted;
    }

    std::vector<std::filesystem::path> written;
    if (setup.writesFile) {
        double denoiseSeconds = 0.0;
        writeOutputs(setup, line, accumulation, run, interrupted, denoiseSeconds);
        summary += " -> " + line.outputPath().string();
        written.push_back(line.outputPath());
        if (line.denoise) {
            char seconds[48];
            std::snprintf(seconds, sizeof seconds, " (denoised in %.2f s)", denoiseSeconds);
            summary += " and " + denoisedPath(line.outputPath()).string() + seconds;
            written.push_back(denoisedPath(line.outputPath()));
        }
        if (line.statisticsOutput) {
            summary += " and " + line.statisticsOutput->string();
            written.push_back(*line.statisticsOutput);
        }
    }
    if (interrupted)
        summary += " (interrupted)";
    if (setup.errorTarget)
        setup.errorTarget->conclude(renderer);
    const RenderEnd end = renderEnd(setup, line, run, interrupted);
    if (setup.errorTarget)
        summary += "; " + setup.errorTarget->summaryText(
                              targetStop(line, *setup.errorTarget, interrupted));
    if (end.exitStatus == kExitTargetNotReached)
        summary += " (exit status " + std::to_string(kExitTargetNotReached) +
                   ": the target error was not reached)";
    report(summary, end, written);
    return end.exitStatus;
}

}  // namespace

int runRender(const CommandLine& commandLine, const InterruptWatch& interrupt)
{
    CommandLine line = commandLine;
    // Ctrl-C during the set-up (the hierarchy over 100,000 objects takes a second or more)
    // ends it at the next step (render::setUpCheckpoint) rather than after the compile.
    struct SetUpInterrupted {};
    render::setSetUpCheckpoint([&interrupt] {
        if (interrupt.requested())
            throw SetUpInterrupted{};
    });
    RenderSetup setup;
    try {
        setup = prepareRender(line);
    } catch (const SetUpInterrupted&) {
        render::setSetUpCheckpoint({});
        std::cout << "interrupted during the set-up: nothing rendered, nothing written"
                  << std::endl;
        return kExitInterrupted;
    }
    render::setSetUpCheckpoint({});
    const RenderRun run = setup.context->hasWindow() ? runInWindow(setup, line, interrupt)
                                                     : runBatch(setup, line, interrupt);
    // A render with an end (SECONDS or --spp) stopped before it by Ctrl-C or by closing its
    // window is interrupted; a window without an end is meant to be closed.
    return finishRender(setup, line, run, interrupt.requested() || run.endedEarly);
}

int printFeatures(const CommandLine& line)
{
    const render::PreparedScene prepared = render::prepareScene(
        scene::parseSceneFile(line.scene), shadergen::shaderBuild(line.settings),
        render::defaultShaderDirectory());
    std::cout << prepared.code.features.describe() << std::flush;
    // The OpenGL a headless render of this command line would use (a window only where
    // --gl window asks for one), and the kernel it would run there.
    platform::ContextRequest request = contextRequest(line);
    request.headless = true;
    const auto context = platform::createContext(request);
    const render::KernelChoice kernel = render::chooseKernel(line.settings.kernel);
    std::cout << "OpenGL:        " << context->identity().describe() << "\n"
              << "kernel:        " << settings::pathKernelName(kernel.kernel) << " ("
              << kernel.reason << ")\n";
    return kExitSuccess;
}

int printShader(const CommandLine& line)
{
    // No context is made: auto prints the fragment kernel's shader.
    const settings::PathKernel kernel = line.settings.kernel == settings::PathKernel::Compute
                                            ? settings::PathKernel::Compute
                                            : settings::PathKernel::Fragment;
    const render::PreparedScene prepared = render::prepareScene(
        scene::parseSceneFile(line.scene), shadergen::shaderBuild(line.settings),
        render::defaultShaderDirectory(), kernel);
    std::cout << prepared.pathTracerSource.text();
    return kExitSuccess;
}

}  // namespace app
