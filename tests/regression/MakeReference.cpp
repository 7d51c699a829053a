// Renders the reference of one regression case (support/RegressionCases.cpp) at its
// reference sample count with the reference seed. Run through tools/update-references.sh,
// which decides what may be overwritten.
//   make_reference --list            the case names, one a line
//   make_reference NAME FILE.exr     renders case NAME into FILE.exr
#include "platform/OsMesaContext.h"
#include "support/ReferenceImage.h"
#include "support/RegressionCases.h"
#include "support/RenderRun.h"

#include <chrono>
#include <cstdio>
#include <exception>
#include <string>

using namespace testing_support;

int main(int argc, char** argv)
{
    try {
        if (argc == 2 && std::string(argv[1]) == "--list") {
            for (const RegressionCase& regressionCase : regressionCases())
                std::printf("%s\n", regressionCase.name.c_str());
            return 0;
        }
        if (argc != 3) {
            std::fprintf(stderr, "usage: make_reference --list | make_reference NAME FILE.exr\n");
            return 2;
        }
        const auto regressionCase = findRegressionCase(argv[1]);
        if (!regressionCase) {
            std::fprintf(stderr, "make_reference: no regression case named '%s'\n", argv[1]);
            return 2;
        }
        const platform::OsMesaContext context;
        const auto start = std::chrono::steady_clock::now();
        const RenderedImage image = renderScene(
            loadScene(scenePath(*regressionCase)), regressionCase->width, regressionCase->height,
            regressionCase->referenceSamplesPerPixel, settingsWithSeed(kReferenceSeed));
        writeReference(
            argv[2], image,
            {regressionCase->scene, regressionCase->referenceSamplesPerPixel, kReferenceSeed});
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::printf("%s: %dx%d, %d spp, seed %llu, %.1f s, %llu samples discarded -> %s\n",
                    regressionCase->name.c_str(), regressionCase->width, regressionCase->height,
                    regressionCase->referenceSamplesPerPixel,
                    static_cast<unsigned long long>(kReferenceSeed), seconds,
                    static_cast<unsigned long long>(image.discardedSamples), argv[2]);
        return 0;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "make_reference: %s\n", error.what());
        return 1;
    }
}
