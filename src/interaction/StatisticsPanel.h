#pragma once
#include "film/ToneCurve.h"
#include "interaction/ConvergenceHistory.h"
#include "settings/RenderSettings.h"

#include <optional>
#include <string>

struct GLFWwindow;
struct ImGuiContext;
struct ImVec2;

namespace interaction {

// What the panel shows, as numbers and lines of text.
struct PanelReadings {
    int width = 0;
    int height = 0;
    int samplesPerPixel = 0;
    double samplesPerSecond = 0.0;
    double elapsedSeconds = 0.0;  // since the accumulation began
    bool previewing = false;      // the view is changing: a coarse sample per frame
    int previewDivisor = 1;
    double previewFramesPerSecond = 0.0;
    std::optional<double> relativeError;
    std::optional<double> targetError;      // --target-error
    std::optional<double> secondsToTarget;  // predicted
    const ConvergenceHistory* history = nullptr;
    std::string features;  // SceneFeatures::describe()
    std::string status;    // the last reload or save, or the error that stopped a reload
    bool statusIsError = false;
};

// What a user tunes while watching. All of it is uniforms: nothing recompiles. The session
// starts it from the renderer's settings.
struct PanelSettings {
    float exposure = film::ToneCurve::kDefaultExposure;
    settings::ToneCurveKind toneCurve = film::ToneCurve::kDefaultCurve;
    float hitTolerance = settings::RenderSettings{}.hitTolerance;
    int maxBounces = settings::RenderSettings{}.maxBounces;
    bool environment = settings::RenderSettings{}.environmentLight;
    // The preview denoiser (render/PreviewDenoiser.h): display only.
    bool previewDenoiser = false;

    bool operator==(const PanelSettings& other) const;
    bool operator!=(const PanelSettings& other) const { return !(*this == other); }
};

// Where the last draw put the panel and its items, in the window's pixels (y down), at the
// scroll it was drawn at: what a test needs to tell that every part of it can be reached.
struct PanelLayout {
    bool shown = false;
    float displayWidth = 0.0f;
    float displayHeight = 0.0f;
    // The panel's window, title bar and scroll bars included.
    float left = 0.0f;
    float top = 0.0f;
    float right = 0.0f;
    float bottom = 0.0f;
    // Where its items show (the window less its title bar, padding and scroll bars).
    float visibleLeft = 0.0f;
    float visibleRight = 0.0f;
    float visibleTop = 0.0f;
    float visibleBottom = 0.0f;
    // The first item's top and the last item's bottom.
    float firstItemTop = 0.0f;
    float lastItemBottom = 0.0f;
    // The right edge of the widest item.
    float contentRight = 0.0f;
    float scrollX = 0.0f;
    float scrollMaxX = 0.0f;
    float scrollY = 0.0f;
    float scrollMaxY = 0.0f;
};

// The on-screen statistics and settings, drawn with Dear ImGui over the picture (Tab shows
// or hides it). It starts hidden: shown, it covers most of a small window and takes the
// mouse drags that start over it, so a fresh window would not answer the mouse. It owns the
// ImGui context and the backends for the window, which must have its input callbacks
// installed before the panel is made (ImGui chains to them).
class StatisticsPanel {
public:
    explicit StatisticsPanel(GLFWwindow* window);
    ~StatisticsPanel();
    StatisticsPanel(const StatisticsPanel&) = delete;
    StatisticsPanel& operator=(const StatisticsPanel&) = delete;

    void toggle() { visible_ = !visible_; }
    bool visible() const { return visible_; }

    // Draws the panel into the bound framebuffer, over what is there, and returns the
    // settings as the user left them.
    PanelSettings draw(const PanelReadings& readings, const PanelSettings& settings);

    const PanelLayout& layout() const { return layout_; }

    // Whether the panel's "write camera line" button was pressed since the last call.
    bool takeCameraLineRequest();

    // The mouse or the keyboard is busy with the panel: the view must not take that input.
    bool wantsMouse() const;
    bool wantsKeyboard() const;

    // The one line of help listing every key and mouse action.
    static const char* const kHelp;

private:
    void recordLayout(const ImVec2& display);

    ImGuiContext* context_ = nullptr;
    bool visible_ = false;
    bool cameraLineRequested_ = false;
    PanelLayout layout_;
};

}  // namespace interaction
