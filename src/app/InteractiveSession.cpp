#include "app/InteractiveSession.h"

#include "app/RenderOutputs.h"
#include "app/SceneDigest.h"
#include "app/SceneLoading.h"
#include "app/Snapshot.h"
#include "film/ConvergenceEstimate.h"
#include "interaction/FramePacing.h"
#include "scene/CameraLine.h"
#include "scene/SceneBounds.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>

namespace app {

namespace {

// The target time of a frame that adds samples: short enough for the panel to answer.
constexpr double kTargetFrameSeconds = 0.15;
// Bounces of a preview sample: enough for light to pass through glass spheres and reach what
// is seen through them (with 2, glass is black), while the longest paths, which cost much and
// add little to a picture that lasts one frame, are cut.
constexpr int kPreviewBounces = 6;
// After the last change of the view, the preview stays this long before the accumulation
// starts: the pause between two mouse events of a slow drag is not a stop.
constexpr double kSettleSeconds = 0.15;
constexpr double kWatchIntervalSeconds = 0.25;
constexpr double kTitleIntervalSeconds = 0.25;
constexpr double kEstimateIntervalSeconds = 0.5;
// The most a held fly key moves the camera in one step, in seconds of flight: a slow frame
// must not make a jump.
constexpr double kLongestFlightStep = 0.1;

double secondsBetween(std::chrono::steady_clock::time_point from,
                      std::chrono::steady_clock::time_point to)
{
    return std::chrono::duration<double>(to - from).count();
}

// A message on one line, for the title.
std::string oneLine(const std::string& text)
{
    std::string line;
    for (char c : text)
        line += c == '\n' ? ' ' : c;
    constexpr std::size_t kLongest = 240;
    if (line.size() > kLongest)
        line = line.substr(0, kLongest) + "...";
    return line;
}

}  // namespace

InteractiveSession::InteractiveSession(platform::GlfwWindowContext& window,
                                       render::ProgressiveRenderer& renderer,
                                       const scene::Scene& scene, const CommandLine& line,
                                       const InterruptWatch& interrupt)
    : window_(window),
      renderer_(renderer),
      line_(line),
      interrupt_(interrupt),
      fileScene_(scene),
      camera_(scene.camera, scene),
      panel_(window.glfwWindow())
{
    watcher_.watch(filesOfScene(line.scene, scene));
    sceneSha256_ = app::sceneSha256(filesOfScene(line.scene, scene));
    panelSettings_.exposure = renderer.exposure();
    panelSettings_.toneCurve = renderer.settings().toneCurve;
    panelSettings_.hitTolerance = renderer.settings().hitTolerance;
    panelSettings_.maxBounces = renderer.settings().maxBounces;
    panelSettings_.environment = renderer.settings().environmentLight;
}

bool InteractiveSession::reachedEnd() const
{
    if (line_.samplesPerPixel && renderer_.samplesPerPixel() >= *line_.samplesPerPixel)
        return true;
    if (targetReached_)
        return true;
    return line_.seconds && secondsBetween(start_, Clock::now()) >= *line_.seconds;
}

bool InteractiveSession::run()
{
    if (!line_.quiet)
        std::cout << "raytracer: Tab shows the statistics panel, with the settings and the keys"
                  << std::endl;
    start_ = Clock::now();
    restartClock();
    lastViewChange_ = start_ - std::chrono::seconds(1);
    lastIteration_ = start_;
    lastWatch_ = start_;
    lastEstimate_ = start_;
    interaction::SamplesPerFrame pacing(line_.settings.samplesPerFrame,
                                        line_.given("--samples-per-frame"), kTargetFrameSeconds);
    bool settingsChanged = false;
    bool reached = false;
    while (!interrupt_.requested() && !window_.closeRequested()) {
        if (reachedEnd()) {
            reached = true;
            break;
        }
        const Clock::time_point now = Clock::now();
        const platform::WindowInput input = window_.takeInput();
        const bool viewChanged = followChanges(input, now, settingsChanged);
        drawNext(input, viewChanged, now, pacing);
        updateErrorEstimate();
        settingsChanged = showFrame(relativeError_);
        if (viewChanged)
            timePreviewFrame(now);
    }
    // What is written at the end is an accumulation, not the coarse picture of a moving view.
    if (renderer_.showsPreview() && (line_.isBatch() || line_.output))
        renderer_.renderFrame({}, 1);
    const Clock::time_point end = Clock::now();
    windowSeconds_ = secondsBetween(start_, end);
    accumulationSeconds_ = secondsBetween(accumulationStart_, end);
    return reached;
}

bool InteractiveSession::followChanges(const platform::WindowInput& input, Clock::time_point now,
                                       bool settingsChanged)
{
    const double sinceLastIteration =
        std::min(secondsBetween(lastIteration_, now), kLongestFlightStep);
    lastIteration_ = now;
    bool viewChanged = answerInput(input, sinceLastIteration) || settingsChanged;
    viewChanged = followWindowSize() || viewChanged;
    if (secondsBetween(lastWatch_, now) >= kWatchIntervalSeconds) {
        lastWatch_ = now;
        if (reloadChangedFiles())
            restartClock();
    }
    if (viewChanged) {
        renderer_.setCamera(camera_.camera());
        lastViewChange_ = now;
        restartClock();
        relativeError_.reset();
        secondsToTarget_.reset();
    }
    return viewChanged;
}

void InteractiveSession::drawNext(const platform::WindowInput& input, bool viewChanged,
                                  Clock::time_point now, interaction::SamplesPerFrame& pacing)
{
    const bool dragging = input.isDown(platform::MouseButton::Left) ||
                          input.isDown(platform::MouseButton::Right) ||
                          input.isDown(platform::MouseButton::Middle);
    const bool settling = secondsBetween(lastViewChange_, now) < kSettleSeconds;
    if (viewChanged) {
        if (previewFrameSeconds_ == 0.0 && renderer_.lastSecondsPerSample() > 0.0)
            previewDivisor_ = interaction::firstPreviewDivisor(renderer_.lastSecondsPerSample());
        renderer_.renderPreview(previewDivisor_, kPreviewBounces);
    } else if (renderer_.showsPreview() && (settling || dragging)) {
        // The view may go on changing: keep the preview, and do not spin.
        window_.waitForInput(0.01);
    } else {
        accumulate(pacing);
    }
}

void InteractiveSession::accumulate(interaction::SamplesPerFrame& pacing)
{
    auto keepGoing = [&] {
        // Input ends a frame between bands, so that the view answers at once.
        return !interrupt_.requested() && !window_.closeRequested() && !window_.hasPendingInput() &&
               !reachedEnd();
    };
    // The first frame shows at once, whatever it will cost.
    int samples = renderer_.frames() == 0 ? 1 : pacing.samples();
    if (line_.samplesPerPixel)
        samples = std::min(samples, *line_.samplesPerPixel - renderer_.samplesPerPixel());
    if (!renderer_.renderFrame(keepGoing, samples))
        return;
    pacing.afterFrame(renderer_.frames(), renderer_.lastSecondsPerSample(),
                      line_.targetError ? secondsToTarget_ : std::nullopt);
    if (rebuildStart_) {
        char text[160];
        std::snprintf(text, sizeof text,
                      "reloaded: structure changed, shader rebuilt; first frame "
                      "%.2f s after the edit was seen",
                      secondsBetween(*rebuildStart_, Clock::now()));
        setStatus(text, false);
        rebuildStart_.reset();
    }
}

void InteractiveSession::updateErrorEstimate()
{
    if (renderer_.showsPreview() || renderer_.samplesPerPixel() < 2 ||
        secondsBetween(lastEstimate_, Clock::now()) < kEstimateIntervalSeconds)
        return;
    lastEstimate_ = Clock::now();
    const auto estimate = film::estimateRelativeError(renderer_.accumulation());
    relativeError_.reset();
    if (estimate)
        relativeError_ = estimate->relativeError;
    const double accumulated = secondsBetween(accumulationStart_, lastEstimate_);
    if (relativeError_)
        history_.add(accumulated, static_cast<float>(*relativeError_));
    // A window given --target-error samples every pixel alike, and ends as a batch render
    // to that target does (ErrorTargetRun).
    if (estimate && line_.targetError) {
        targetReached_ = estimate->upperBound() <= *line_.targetError &&
                         renderer_.samplesPerPixel() >= line_.adaptiveSampling.minimumSamples;
        secondsToTarget_ =
            history_.secondsLeftToReach(*line_.targetError, accumulated, estimate->upperBound());
    }
}

void InteractiveSession::timePreviewFrame(Clock::time_point frameStart)
{
    const double frameSeconds = secondsBetween(frameStart, Clock::now());
    previewDivisor_ = interaction::nextPreviewDivisor(previewDivisor_, frameSeconds);
    // Smoothed over about ten frames, for the title and the panel.
    previewFrameSeconds_ =
        previewFrameSeconds_ > 0.0 ? 0.9 * previewFrameSeconds_ + 0.1 * frameSeconds : frameSeconds;
}

bool InteractiveSession::answerInput(const platform::WindowInput& input, double seconds)
{
    const scene::Camera before = camera_.camera();
    if (!panel_.wantsMouse()) {
        const float height = static_cast<float>(std::max(window_.windowSize().height, 1));
        camera_.orbit(input.dragOf(platform::MouseButton::Left), height);
        camera_.pan(input.dragOf(platform::MouseButton::Right) +
                        input.dragOf(platform::MouseButton::Middle),
                    height);
        camera_.dolly(input.wheelSteps);
    }
    if (!panel_.wantsKeyboard()) {
        for (const platform::KeyPress& press : input.keyPresses) {
            if (press.key == platform::Key::Tab)
                panel_.toggle();
            else if (press.key == platform::Key::R && !press.control)
                camera_.returnHome();
            else if (press.key == platform::Key::S && press.control)
                save();
            else if (press.key == platform::Key::C && !press.control)
                writeCameraLine();
            else if (press.key == platform::Key::N) {
                panelSettings_.previewDenoiser = !panelSettings_.previewDenoiser;
                renderer_.setPreviewDenoising(panelSettings_.previewDenoiser);
            }
        }
        // Ctrl makes a key a command (Ctrl+S), not a flight.
        if (!input.controlHeld) {
            using platform::Key;
            const glm::vec3 direction(
                static_cast<float>(input.held(Key::D)) - static_cast<float>(input.held(Key::A)),
                static_cast<float>(input.held(Key::E)) - static_cast<float>(input.held(Key::Q)),
                static_cast<float>(input.held(Key::W)) - static_cast<float>(input.held(Key::S)));
            camera_.fly(direction, static_cast<float>(seconds), input.shiftHeld);
        }
    }
    return !scene::sameCamera(before, camera_.camera());
}

bool InteractiveSession::applyPanelSettings(const interaction::PanelSettings& tuned)
{
    if (tuned == panelSettings_)
        return false;
    renderer_.setExposure(tuned.exposure);
    renderer_.setPreviewDenoising(tuned.previewDenoiser);
    renderer_.setToneCurve(tuned.toneCurve);
    const bool viewChanged = tuned.hitTolerance != panelSettings_.hitTolerance ||
                             tuned.maxBounces != panelSettings_.maxBounces ||
                             tuned.environment != panelSettings_.environment;
    panelSettings_ = tuned;
    if (!viewChanged)
        return false;
    settings::RenderSettings settings = renderer_.settings();
    settings.hitTolerance = tuned.hitTolerance;
    settings.maxBounces = tuned.maxBounces;
    settings.environmentLight = tuned.environment;
    renderer_.setSettings(settings);
    return true;
}

bool InteractiveSession::followWindowSize()
{
    const platform::DrawableSize size = window_.windowFramebufferSize();
    if (size.width <= 0 || size.height <= 0 ||
        (size.width == renderer_.width() && size.height == renderer_.height()))
        return false;
    try {
        renderer_.resize(size.width, size.height);
    } catch (const std::exception& error) {
        setStatus(std::string("cannot render at the window's size: ") + error.what(), true);
        return false;
    }
    return true;
}

bool InteractiveSession::reloadChangedFiles()
{
    const std::vector<std::filesystem::path> changed = watcher_.changedFiles();
    if (changed.empty())
        return false;
    const Clock::time_point start = Clock::now();
    try {
        scene::Scene edited = loadScene(line_.scene);
        if (line_.camera)
            edited.camera = *line_.camera;  // --camera stands for the file's camera
        std::string editedSha256 = app::sceneSha256(filesOfScene(line_.scene, edited));
        const Clock::time_point loaded = Clock::now();
        interaction::CameraController camera = camera_;
        camera.setHome(edited.camera, edited,
                       render::cameraLinesChanged(fileScene_.camera, edited.camera));
        scene::Scene shown = edited;
        shown.camera = camera.camera();
        const render::ReloadDecision decision = renderer_.setScene(shown, changed);
        const double readSeconds = secondsBetween(start, loaded);
        const double uploadSeconds = secondsBetween(loaded, Clock::now());
        camera_ = camera;
        fileScene_ = std::move(edited);
        sceneSha256_ = std::move(editedSha256);
        watcher_.watch(filesOfScene(line_.scene, fileScene_));
        if (decision.changesNothing) {
            setStatus("the edit changes nothing on screen (a comment, spacing): the "
                      "accumulation goes on",
                      false);
            return false;
        }
        char text[200];
        if (decision.rebuildShader) {
            std::snprintf(text, sizeof text,
                          "reloaded: structure changed, shader rebuilt (compile and link "
                          "%.2f s)%s",
                          renderer_.compileSeconds(),
                          decision.reloadTextures ? ", textures reloaded" : "");
            rebuildStart_ = start;
        } else {
            std::snprintf(text, sizeof text,
                          "reloaded: values only, uniforms re-uploaded without a recompile "
                          "(reading the file %.1f ms, uploading and restarting the "
                          "accumulation %.1f ms)%s",
                          1000.0 * readSeconds, 1000.0 * uploadSeconds,
                          decision.reloadTextures ? ", textures reloaded" : "");
            rebuildStart_.reset();
        }
        setStatus(text, false);
        history_.clear();
        return true;
    } catch (const std::exception& error) {
        setStatus(std::string("error: ") + error.what() + " (the last good scene stays on screen)",
                  true);
        return false;
    }
}

void InteractiveSession::save()
{
    if (renderer_.showsPreview() || renderer_.samplesPerPixel() == 0) {
        setStatus("nothing to save yet: the image has no samples while the view changes", true);
        return;
    }
    const SnapshotFiles files =
        snapshotFiles(line_.scene, renderer_.samplesPerPixel(), line_.output);
    try {
        film::RenderMetadata metadata =
            describeRender(line_.scene, sceneSha256_, renderer_, window_.identity());
        metadata.renderSeconds = secondsBetween(accumulationStart_, Clock::now());
        writeSnapshot(renderer_, files, metadata);
        setStatus("saved " + files.picture.string() + " and " + files.radiance.string(), false);
    } catch (const std::exception& error) {
        setStatus(std::string("error: cannot save: ") + error.what(), true);
    }
}

void InteractiveSession::writeCameraLine()
{
    const std::string line = scene::cameraLine(camera_.camera());
    // On a line of its own, ready to paste over the scene file's camera.
    std::cout << line << std::endl;
    std::filesystem::path file = line_.scene;
    file.replace_extension(".camera");
    {
        std::ofstream out(file, std::ios::trunc);
        out << "# The window's camera for " << line_.scene.filename().string()
            << ": eye, look-at point, up, field of view; paste it over the scene's camera.\n"
            << line << "\n";
        out.flush();
        if (!out) {
            setStatus("camera line printed; cannot write " + file.string() + ": " +
                          std::strerror(errno),
                      true);
            return;
        }
    }
    setStatus("camera line printed and written to " + file.string() + ": " + line, false);
}

void InteractiveSession::setStatus(std::string status, bool isError)
{
    status_ = std::move(status);
    statusIsError_ = isError;
    if (isError)
        std::cerr << "raytracer: " << status_ << std::endl;
    else
        std::cout << "raytracer: " << status_ << std::endl;
    window_.setTitle(title());
}

void InteractiveSession::restartClock()
{
    accumulationStart_ = Clock::now();
    history_.clear();
}

bool InteractiveSession::showFrame(const std::optional<double>& relativeError)
{
    const platform::DrawableSize size = window_.windowFramebufferSize();
    if (size.width <= 0 || size.height <= 0) {
        window_.waitForInput(0.05);  // minimised: nothing to draw
        return false;
    }
    renderer_.displayToWindow(size.width, size.height);
    interaction::PanelReadings readings;
    readings.width = renderer_.width();
    readings.height = renderer_.height();
    readings.samplesPerPixel = renderer_.samplesPerPixel();
    readings.elapsedSeconds = secondsBetween(accumulationStart_, Clock::now());
    readings.samplesPerSecond =
        readings.elapsedSeconds > 0.0 ? readings.samplesPerPixel / readings.elapsedSeconds : 0.0;
    readings.previewing = renderer_.showsPreview();
    readings.previewDivisor = previewDivisor_;
    readings.previewFramesPerSecond = previewFrameSeconds_ > 0.0 ? 1.0 / previewFrameSeconds_ : 0.0;
    readings.relativeError = relativeError;
    readings.targetError = line_.targetError;
    readings.secondsToTarget = secondsToTarget_;
    readings.history = &history_;
    readings.features = renderer_.features().describe();
    readings.status = status_;
    readings.statusIsError = statusIsError_;
    const interaction::PanelSettings tuned = panel_.draw(readings, panelSettings_);
    window_.present();
    if (panel_.takeCameraLineRequest())
        writeCameraLine();
    if (secondsBetween(lastTitle_, Clock::now()) >= kTitleIntervalSeconds) {
        window_.setTitle(title());
        lastTitle_ = Clock::now();
    }
    return applyPanelSettings(tuned);
}

std::string InteractiveSession::title() const
{
    const double elapsed = secondsBetween(accumulationStart_, Clock::now());
    char text[160];
    std::snprintf(text, sizeof text, "raytracer - %s - %dx%d - %d spp, %.2f spp/s",
                  line_.scene.filename().string().c_str(), renderer_.width(), renderer_.height(),
                  renderer_.samplesPerPixel(),
                  elapsed > 0.0 ? renderer_.samplesPerPixel() / elapsed : 0.0);
    std::string result = text;
    if (renderer_.showsPreview()) {
        std::snprintf(text, sizeof text, " - moving, %.1f fps at 1/%d resolution",
                      previewFrameSeconds_ > 0.0 ? 1.0 / previewFrameSeconds_ : 0.0,
                      previewDivisor_);
        result += text;
    }
    if (!status_.empty())
        result += " - " + oneLine(status_);
    return result;
}

}  // namespace app
