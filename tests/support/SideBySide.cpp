#include "support/SideBySide.h"

#include "io/ImageFile.h"

#include <algorithm>
#include <cmath>

namespace testing_support {

namespace {

constexpr int kEnlargement = 4;
constexpr int kGap = 4;

float display(float radiance)
{
    const float positive = std::max(radiance, 0.0f);
    return std::pow(positive / (1.0f + positive), 1.0f / 2.2f);
}

}  // namespace

std::filesystem::path writeSideBySide(const std::filesystem::path& path,
                                      const RenderedImage& reference, const RenderedImage& render,
                                      const Comparison& comparison, int blockSize)
{
    const int width = reference.width();
    const int height = reference.height();
    const int panelWidth = width * kEnlargement;
    const int panels = 4;
    io::Image picture(panels * panelWidth + (panels - 1) * kGap, height * kEnlargement, 3);
    std::fill(picture.pixels.begin(), picture.pixels.end(), 1.0f);

    auto panelColour = [&](int panel, int x, int y, int c) -> float {
        switch (panel) {
        case 0:
            return display(reference.radiance.at(x, y, c));
        case 1:
            return display(render.radiance.at(x, y, c));
        case 2:
            return display(kDifferenceMagnification *
                           std::abs(render.radiance.at(x, y, c) - reference.radiance.at(x, y, c)));
        default: {
            const int b = (y / blockSize) * comparison.blocksX + x / blockSize;
            const double z = comparison.channelMeanZ[b];
            const float strength = static_cast<float>(std::min(std::abs(z) / 4.0, 1.0));
            const bool brighter = z > 0.0;
            if (c == 0)
                return brighter ? 1.0f : 1.0f - strength;
            if (c == 2)
                return brighter ? 1.0f - strength : 1.0f;
            return 1.0f - strength;
        }
        }
    };

    for (int panel = 0; panel < panels; ++panel)
        for (int y = 0; y < picture.height; ++y)
            for (int x = 0; x < panelWidth; ++x)
                for (int c = 0; c < 3; ++c)
                    picture.at(panel * (panelWidth + kGap) + x, y, c) = std::clamp(
                        panelColour(panel, x / kEnlargement, y / kEnlargement, c), 0.0f, 1.0f);

    std::filesystem::create_directories(path.parent_path());
    io::writeImage(path, picture);
    return path;
}

}  // namespace testing_support
