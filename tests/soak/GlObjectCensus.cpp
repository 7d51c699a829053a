// The soak run's in-process half (tools/soak.sh; not a ctest test): renders a scene frame by
// frame in one GL context, replaces the scene every few seconds (ProgressiveRenderer::setScene,
// alternating two scenes whose shaders differ, so the program is rebuilt each time), and once
// a minute (or every REPORT_SECONDS) prints the process's resident memory and how many GL
// objects of each kind are alive, found by asking glIs* of every name up to a bound. A leak
// shows as a count or the memory that grows with the frames.
//   gl_object_census SCENE_A SCENE_B WIDTH HEIGHT FRAMES MAX_SECONDS RELOAD_SECONDS
//                    [REPORT_SECONDS]
#include "gl/EntryPoints.h"
#include "platform/ContextFactory.h"
#include "render/ProgressiveRenderer.h"
#include "scene/SceneParser.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

// src/gl/EntryPoints.cpp routes this to the current context's loader (OSMesa or GLFW); the
// renderer has no use for glIsTexture, a GL 1.1 function, so it is looked up here.
extern "C" void (*glXGetProcAddressARB(const GLubyte* name))();

namespace {

long residentKilobytes()
{
    std::ifstream status("/proc/self/status");
    std::string key;
    while (status >> key) {
        if (key == "VmRSS:") {
            long kilobytes = 0;
            status >> kilobytes;
            return kilobytes;
        }
        status.ignore(4096, '\n');
    }
    return -1;
}

struct Census {
    int textures = 0, framebuffers = 0, programs = 0, shaders = 0, vertexArrays = 0, buffers = 0;
};

// Names are small integers handed out from 1; 65536 is far past what a run creates.
Census takeCensus()
{
    const auto isTexture = reinterpret_cast<GLboolean (*)(GLuint)>(
        glXGetProcAddressARB(reinterpret_cast<const GLubyte*>("glIsTexture")));
    Census census;
    for (GLuint name = 1; name <= 65536; ++name) {
        census.textures += isTexture(name) ? 1 : 0;
        census.framebuffers += glIsFramebuffer(name) ? 1 : 0;
        census.programs += glIsProgram(name) ? 1 : 0;
        census.shaders += glIsShader(name) ? 1 : 0;
        census.vertexArrays += glIsVertexArray(name) ? 1 : 0;
        census.buffers += glIsBuffer(name) ? 1 : 0;
    }
    return census;
}

}  // namespace

int main(int argc, char* argv[])
{
    if (argc != 8 && argc != 9) {
        std::cerr << "usage: gl_object_census SCENE_A SCENE_B WIDTH HEIGHT FRAMES MAX_SECONDS "
                     "RELOAD_SECONDS [REPORT_SECONDS]\n";
        return 2;
    }
    try {
        const scene::Scene scenes[2] = {scene::parseSceneFile(argv[1]),
                                        scene::parseSceneFile(argv[2])};
        const int width = std::atoi(argv[3]);
        const int height = std::atoi(argv[4]);
        const long frames = std::atol(argv[5]);
        const double maxSeconds = std::atof(argv[6]);
        const double reloadSeconds = std::atof(argv[7]);
        const double reportSeconds = argc == 9 ? std::atof(argv[8]) : 60.0;

        platform::ContextRequest request;
        request.headless = !platform::displayAvailable();
        request.windowWidth = width;
        request.windowHeight = height;
        auto context = platform::createContext(request);
        settings::RenderSettings settings;
        settings.samplesPerFrame = 1;
        settings.secondsPerBand = 0.0;
        render::ProgressiveRenderer renderer(scenes[0], width, height, settings);

        using Clock = std::chrono::steady_clock;
        const auto start = Clock::now();
        auto since = [](Clock::time_point t) {
            return std::chrono::duration<double>(Clock::now() - t).count();
        };
        auto report = [&](long frame, int reloads) {
            const Census census = takeCensus();
            std::printf("%.0f s, frame %ld, %d reloads: RSS %ld kB; GL objects alive: %d "
                        "textures, %d framebuffers, %d programs, %d shaders, %d vertex arrays, "
                        "%d buffers\n",
                        since(start), frame, reloads, residentKilobytes(), census.textures,
                        census.framebuffers, census.programs, census.shaders, census.vertexArrays,
                        census.buffers);
            std::fflush(stdout);
        };
        auto lastReport = start;
        auto lastReload = start;
        int reloads = 0;
        long frame = 0;
        report(frame, reloads);
        for (; frame < frames && since(start) < maxSeconds; ++frame) {
            renderer.renderFrame();
            if (context->hasWindow()) {
                renderer.displayToWindow(width, height);
                context->present();
            }
            if (reloadSeconds > 0.0 && since(lastReload) >= reloadSeconds) {
                ++reloads;
                renderer.setScene(scenes[reloads % 2]);
                lastReload = Clock::now();
            }
            if (since(lastReport) >= reportSeconds) {
                report(frame + 1, reloads);
                lastReport = Clock::now();
            }
        }
        report(frame, reloads);
    } catch (const std::exception& error) {
        std::cerr << "gl_object_census: " << error.what() << "\n";
        return 1;
    }
    return 0;
}
