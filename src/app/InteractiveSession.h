#pragma once
#include "app/CommandLine.h"
#include "app/Interrupt.h"
#include "interaction/CameraController.h"
#include "interaction/ConvergenceHistory.h"
#include "interaction/FileWatcher.h"
#include "interaction/FramePacing.h"
#include "interaction/StatisticsPanel.h"
#include "platform/GlfwWindowContext.h"
#include "render/ProgressiveRenderer.h"
#include "scene/Scene.h"

#include <chrono>
#include <optional>
#include <string>

namespace app {

// The window: it shows the estimate converging and answers the user. The mouse and the
// keys move the camera (interaction::CameraController); while the view changes, each frame is
// one cheap sample on a coarse grid, and once it stops the accumulation goes on at full
// rate. The scene file and the files it names are watched: an edit of values re-uploads
// uniforms, an edit of structure rebuilds the shader, a broken edit leaves the last good
// scene on screen with the error in the panel, the title and on standard error. Ctrl+S
// saves PNG + EXR; C (or the panel's button) writes the camera as a scene-file line to the
// terminal and to SCENE.camera beside the scene; Tab shows or hides the statistics panel; a
// resized window renders at its new size.
class InteractiveSession {
public:
    // `scene`: the scene file as loaded, whose shader `renderer` was built with (with
    // switchableEnvironment, for the panel's environment switch).
    InteractiveSession(platform::GlfwWindowContext& window, render::ProgressiveRenderer& renderer,
                       const scene::Scene& scene, const CommandLine& line,
                       const InterruptWatch& interrupt);

    // Runs until the window is closed, Ctrl-C, or the end the command line sets (SECONDS or
    // --spp). True when that end was reached; a window closed before it is an interrupted
    // render. The renderer then holds an accumulation, never a preview.
    bool run();

    // Seconds from the start of run to its end: the time the window was open.
    double windowSeconds() const { return windowSeconds_; }
    // Seconds the accumulation on screen at the end took: from the last change of the view,
    // scene or settings that restarted it to the end of run.
    double accumulationSeconds() const { return accumulationSeconds_; }
    // SHA-256 of the files of the scene on screen (app/SceneDigest.h): the one last loaded.
    const std::string& sceneSha256() const { return sceneSha256_; }

private:
    using Clock = std::chrono::steady_clock;

    // The end the command line set (SECONDS, --spp, --target-error) is reached.
    bool reachedEnd() const;
    // Follows the input, the window's size and the files watched; true when the view
    // changed, which uploads the camera and restarts the accumulation.
    bool followChanges(const platform::WindowInput& input, Clock::time_point now,
                       bool settingsChanged);
    // The next picture: a preview while the view changes, none while it may go on changing
    // (a drag, a pause between its events), else more samples.
    void drawNext(const platform::WindowInput& input, bool viewChanged, Clock::time_point now,
                  interaction::SamplesPerFrame& pacing);
    void accumulate(interaction::SamplesPerFrame& pacing);
    // Now and then, the estimate of the image's error and, with --target-error, of the time
    // left to it.
    void updateErrorEstimate();
    // The preview's resolution follows the time its frame (started at `frameStart`) took.
    void timePreviewFrame(Clock::time_point frameStart);
    // Moves the camera and acts on keys; true when the view changed.
    bool answerInput(const platform::WindowInput& input, double seconds);
    // Settings tuned in the panel; true when the view changed (exposure does not change it).
    bool applyPanelSettings(const interaction::PanelSettings& tuned);
    // A window of another size renders at that size; true when it changed.
    bool followWindowSize();
    // Reloads the scene when the bytes of one of its files changed; true when the scene on
    // screen was replaced (not when the edit changes nothing the GPU is given).
    bool reloadChangedFiles();
    void save();
    // The camera on screen as a scene file's camera line (scene::cameraLine), on standard
    // output and in SCENE.camera beside the scene file.
    void writeCameraLine();
    void setStatus(std::string status, bool isError);
    void restartClock();
    // Draws the estimate and the panel, and shows them; true when the panel changed a
    // setting that changes the view.
    bool showFrame(const std::optional<double>& relativeError);
    std::string title() const;

    platform::GlfwWindowContext& window_;
    render::ProgressiveRenderer& renderer_;
    const CommandLine& line_;
    const InterruptWatch& interrupt_;
    scene::Scene fileScene_;   // as last read from the file, its camera the file's
    std::string sceneSha256_;  // of fileScene_'s files, as read
    interaction::CameraController camera_;
    interaction::FileWatcher watcher_;
    interaction::StatisticsPanel panel_;
    interaction::PanelSettings panelSettings_;
    interaction::ConvergenceHistory history_;
    bool targetReached_ = false;             // --target-error
    std::optional<double> relativeError_;    // estimated, every kEstimateIntervalSeconds
    std::optional<double> secondsToTarget_;  // predicted, from history_
    std::string status_;
    bool statusIsError_ = false;
    int previewDivisor_ = 2;
    double previewFrameSeconds_ = 0.0;  // smoothed time of a frame while the view changes
    Clock::time_point start_;           // of run()
    Clock::time_point accumulationStart_;
    Clock::time_point lastViewChange_;
    Clock::time_point lastIteration_;
    Clock::time_point lastWatch_;
    Clock::time_point lastEstimate_;
    Clock::time_point lastTitle_;
    // A structural reload: when it started, until the first frame after it is drawn.
    std::optional<Clock::time_point> rebuildStart_;
    double windowSeconds_ = 0.0;
    double accumulationSeconds_ = 0.0;
};

}  // namespace app
