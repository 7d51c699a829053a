#include "interaction/StatisticsPanel.h"

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace interaction {

const char* const StatisticsPanel::kHelp =
    "left drag: orbit   right/middle drag: pan   wheel: dolly   W A S D Q E: fly "
    "(Shift: faster)   R: the file's camera   C: write the camera as a scene-file line   "
    "N: preview denoiser   Ctrl+S: save PNG + EXR   Tab: this panel   Esc: quit";

bool PanelSettings::operator==(const PanelSettings& other) const
{
    return exposure == other.exposure && toneCurve == other.toneCurve &&
           hitTolerance == other.hitTolerance && maxBounces == other.maxBounces &&
           environment == other.environment && previewDenoiser == other.previewDenoiser;
}

namespace {

// Text wraps at this width, or the window's less a margin: the panel stays narrow enough
// to leave the picture visible.
constexpr float kWrapWidth = 330.0f;
// The panel's margin from the window's edges.
constexpr float kMargin = 4.0f;

}  // namespace

StatisticsPanel::StatisticsPanel(GLFWwindow* window)
{
    IMGUI_CHECKVERSION();
    context_ = ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    // No imgui.ini in the user's folder.
    io.IniFilename = nullptr;
    ImGui::StyleColorsDark();
    if (!ImGui_ImplGlfw_InitForOpenGL(window, /*install_callbacks=*/true)) {
        ImGui::DestroyContext(context_);
        throw std::runtime_error("cannot set up the statistics panel (ImGui for GLFW)");
    }
    if (!ImGui_ImplOpenGL3_Init("#version 330 core")) {
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext(context_);
        throw std::runtime_error("cannot set up the statistics panel (ImGui for OpenGL 3)");
    }
}

StatisticsPanel::~StatisticsPanel()
{
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext(context_);
}

bool StatisticsPanel::takeCameraLineRequest()
{
    const bool requested = cameraLineRequested_;
    cameraLineRequested_ = false;
    return requested;
}

bool StatisticsPanel::wantsMouse() const
{
    return visible_ && ImGui::GetIO().WantCaptureMouse;
}

bool StatisticsPanel::wantsKeyboard() const
{
    return visible_ && ImGui::GetIO().WantCaptureKeyboard;
}

void StatisticsPanel::recordLayout(const ImVec2& display)
{
    // Called after the last item, inside the panel's Begin and End.
    const ImGuiWindow* window = ImGui::GetCurrentWindow();
    layout_.shown = true;
    layout_.displayWidth = display.x;
    layout_.displayHeight = display.y;
    layout_.left = window->Pos.x;
    layout_.top = window->Pos.y;
    layout_.right = window->Pos.x + window->Size.x;
    layout_.bottom = window->Pos.y + window->Size.y;
    layout_.visibleLeft = window->InnerClipRect.Min.x;
    layout_.visibleRight = window->InnerClipRect.Max.x;
    layout_.visibleTop = window->InnerClipRect.Min.y;
    layout_.visibleBottom = window->InnerClipRect.Max.y;
    layout_.lastItemBottom = ImGui::GetItemRectMax().y;
    layout_.contentRight = window->DC.CursorMaxPos.x;
    layout_.scrollX = ImGui::GetScrollX();
    layout_.scrollMaxX = ImGui::GetScrollMaxX();
    layout_.scrollY = ImGui::GetScrollY();
    layout_.scrollMaxY = ImGui::GetScrollMaxY();
}

PanelSettings StatisticsPanel::draw(const PanelReadings& readings, const PanelSettings& settings)
{
    PanelSettings tuned = settings;
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    layout_ = PanelLayout{};
    if (visible_) {
        // Never larger than the window: in a small window the panel scrolls (the wheel over
        // it, or its scroll bar), so that every part of it can be reached.
        const ImVec2 display = ImGui::GetIO().DisplaySize;
        const float wrapWidth = std::max(100.0f, std::min(kWrapWidth, display.x - 6.0f * kMargin));
        ImGui::SetNextWindowPos(ImVec2(kMargin, kMargin), ImGuiCond_FirstUseEver);
        ImGui::SetNextWindowSizeConstraints(ImVec2(0.0f, 0.0f),
                                            ImVec2(std::max(display.x - 2.0f * kMargin, 50.0f),
                                                   std::max(display.y - 2.0f * kMargin, 50.0f)));
        ImGui::SetNextWindowBgAlpha(0.75f);
        ImGui::Begin("statistics (Tab hides)", nullptr,
                     ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoFocusOnAppearing |
                         ImGuiWindowFlags_HorizontalScrollbar);
        ImGui::Text("%dx%d   %d spp   %.2f spp/s   %.1f s", readings.width, readings.height,
                    readings.samplesPerPixel, readings.samplesPerSecond, readings.elapsedSeconds);
        layout_.firstItemTop = ImGui::GetItemRectMin().y;
        if (readings.previewing)
            ImGui::Text("moving: 1 sample per frame, 1/%d resolution, %.1f fps",
                        readings.previewDivisor, readings.previewFramesPerSecond);
        else if (readings.relativeError)
            ImGui::Text("remaining error (rel. RMS, from the variance): %.2f%%",
                        100.0 * *readings.relativeError);
        else
            ImGui::Text("remaining error: needs 2 samples per pixel");
        if (readings.targetError && !readings.previewing) {
            if (readings.secondsToTarget)
                ImGui::Text("target %.2f%%: about %.0f s left", 100.0 * *readings.targetError,
                            *readings.secondsToTarget);
            else
                ImGui::Text("target %.2f%%", 100.0 * *readings.targetError);
        }
        if (readings.history != nullptr && !readings.history->errors().empty()) {
            const auto& errors = readings.history->errors();
            char caption[64];
            std::snprintf(caption, sizeof caption, "error vs time, 0-%.0f s",
                          readings.history->lastSeconds());
            float largest = 0.0f;
            for (float error : errors)
                largest = std::max(largest, error);
            ImGui::PlotLines("##convergence", errors.data(), static_cast<int>(errors.size()), 0,
                             caption, 0.0f, largest, ImVec2(wrapWidth - 10.0f, 50.0f));
        }

        ImGui::Separator();
        ImGui::PushItemWidth(150.0f);
        ImGui::SliderFloat("exposure", &tuned.exposure, 0.25f, 32.0f, "%.2f",
                           ImGuiSliderFlags_Logarithmic);
        // The curves --tone-curve names, in their order (settings/Choices.h).
        const auto& curves = settings::Choices<settings::ToneCurveKind>::values;
        int curve = settings::choiceCode(tuned.toneCurve);
        if (ImGui::Combo(
                "tone curve", &curve,
                [](void*, int i, const char** name) {
                    *name = settings::Choices<settings::ToneCurveKind>::values[i].name;
                    return true;
                },
                nullptr, static_cast<int>(curves.size())))
            tuned.toneCurve = curves[curve].value;
        ImGui::SliderFloat("hit tolerance", &tuned.hitTolerance, 0.01f, 4.0f, "%.3f px",
                           ImGuiSliderFlags_Logarithmic);
        ImGui::SliderInt("max bounces", &tuned.maxBounces, 0, 64);
        ImGui::PopItemWidth();
        ImGui::Checkbox("environment light", &tuned.environment);
        if (ImGui::Button("write camera line (C)"))
            cameraLineRequested_ = true;
        ImGui::Checkbox("preview denoiser (N)", &tuned.previewDenoiser);

        if (!readings.status.empty()) {
            ImGui::Separator();
            ImGui::PushTextWrapPos(wrapWidth);
            if (readings.statusIsError)
                ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", readings.status.c_str());
            else
                ImGui::TextUnformatted(readings.status.c_str());
            ImGui::PopTextWrapPos();
        }
        if (ImGui::CollapsingHeader("shader features", ImGuiTreeNodeFlags_DefaultOpen))
            ImGui::TextUnformatted(readings.features.c_str());
        ImGui::Separator();
        ImGui::PushTextWrapPos(wrapWidth);
        ImGui::TextDisabled("%s", kHelp);
        ImGui::TextDisabled("resizing the window renders at its new size");
        ImGui::PopTextWrapPos();
        recordLayout(display);
        ImGui::End();
    }
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    return tuned;
}

}  // namespace interaction
