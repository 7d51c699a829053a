#include "app/BuildInfo.h"
#include "app/CommandLine.h"
#include "app/InfoCommand.h"
#include "app/MergeCommand.h"
#include "app/RenderCommand.h"

#include <exception>
#include <iostream>

int main(int argc, char* argv[])
{
    try {
        const app::CommandLine line = app::parseCommandLine(argc, argv);
        switch (line.action) {
        case app::Action::Help:
            std::cout << app::usageText();
            return app::kExitSuccess;
        case app::Action::Version:
            std::cout << app::programName()
                      << (app::gitCommit().empty() ? "" : " (commit " + app::gitCommit() + ")")
                      << "\n";
            return app::kExitSuccess;
        case app::Action::PrintFeatures:
            return app::printFeatures(line);
        case app::Action::PrintShader:
            return app::printShader(line);
        case app::Action::Render:
            return app::runRender(line);
        case app::Action::Info:
            return app::runInfo(line.infoFile);
        case app::Action::Merge:
            return app::runMerge(line.merge);
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
