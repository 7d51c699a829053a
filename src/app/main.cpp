#include "app/BuildInfo.h"
#include "app/CommandLine.h"
#include "app/Denoising.h"
#include "app/InfoCommand.h"
#include "app/Interrupt.h"
#include "app/MergeCommand.h"
#include "app/RenderCommand.h"

#include <exception>
#include <iostream>

namespace {

// A command that does not watch for interrupts itself (help, info, ...) ends as interrupted
// when one came while it ran.
int unlessInterrupted(const app::InterruptWatch& interrupt, int status)
{
    if (!interrupt.requested())
        return status;
    std::cerr << "raytracer: interrupted\n";
    return app::kExitInterrupted;
}

}  // namespace

int main(int argc, char* argv[])
{
    // First: a Ctrl-C or SIGTERM from the very start, held pending by the launcher while the
    // libraries loaded, ends the program as documented (app/Interrupt.h).
    const app::InterruptWatch interrupt;
    try {
        const app::CommandLine line = app::parseCommandLine(argc, argv);
        switch (line.action) {
        case app::Action::Help:
            std::cout << app::usageText();
            return unlessInterrupted(interrupt, app::kExitSuccess);
        case app::Action::Version:
            std::cout << app::programName()
                      << (app::gitCommit().empty() ? "" : " (commit " + app::gitCommit() + ")")
                      << "\n";
            return unlessInterrupted(interrupt, app::kExitSuccess);
        case app::Action::PrintFeatures:
            return unlessInterrupted(interrupt, app::printFeatures(line));
        case app::Action::PrintShader:
            return unlessInterrupted(interrupt, app::printShader(line));
        case app::Action::Render:
            return app::runRender(line, interrupt);
        case app::Action::Info:
            return unlessInterrupted(interrupt, app::runInfo(line.infoFile));
        case app::Action::Merge:
            return app::runMerge(line.merge, interrupt);
        case app::Action::Denoise:
            return unlessInterrupted(interrupt, app::runDenoise(line.denoising));
        }
    } catch (const app::UsageError& error) {
        std::cerr << "raytracer: " << error.what() << "\n";
        return app::kExitUsage;
    } catch (const std::exception& error) {
        std::cerr << "raytracer: " << error.what() << "\n";
        return app::kExitFailure;
    }
    return app::kExitFailure;
}
