#include "app/Denoising.h"

#include "app/RenderCommand.h"
#include "film/Denoiser.h"
#include "film/RenderFile.h"
#include "film/ToneCurve.h"
#include "io/ImageFile.h"
#include "io/ImageFormats.h"

#include <chrono>
#include <cstdio>
#include <iostream>
#include <stdexcept>

namespace app {

namespace fs = std::filesystem;

fs::path denoisedPath(const fs::path& output)
{
    fs::path path = output;
    return path.replace_filename(output.stem().string() + ".denoised" +
                                 output.extension().string());
}

io::Image denoisedRadiance(const film::Accumulation& accumulation)
{
    if (!accumulation.hasFeatures())
        throw std::runtime_error("this render has no feature buffers to guide the denoiser: "
                                 "render it with --feature-buffers (or --denoise)");
    const int width = accumulation.width();
    const int height = accumulation.height();
    io::Image albedo(width, height, 3);
    io::Image normal(width, height, 3);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < 3; ++c) {
                albedo.at(x, y, c) = accumulation.albedoDepth.at(x, y, c);
                normal.at(x, y, c) = accumulation.normalCoverage.at(x, y, c);
            }
    return film::denoiseImage(film::meanRadiance(accumulation), albedo, normal);
}

io::OutputImage denoisedOutput(const fs::path& path, const io::Image& denoised,
                               const film::RenderMetadata& metadata, const fs::path& rawFile)
{
    std::vector<io::ImageAttribute> attributes = film::metadataAttributes(metadata);
    attributes.push_back(
        {"raytracer:denoised", "Open Image Denoise (RT filter, HDR, guided by the first-hit albedo "
                               "and normal; " +
                                   film::denoiserLibrary() + ") from " + rawFile.string() +
                                   ": biased, not to be merged or resumed"});
    if (io::holdsLinearRadiance(path))
        return {path, denoised, std::move(attributes), {}};
    // The exposure and curve the render records (the same as its raw picture's).
    io::Image picture(denoised.width, denoised.height, 3);
    for (std::size_t i = 0; i + 2 < picture.pixels.size(); i += 3) {
        const film::Rgb shown = film::displayColour(
            {denoised.pixels[i], denoised.pixels[i + 1], denoised.pixels[i + 2]},
            metadata.settings.exposure, metadata.settings.toneCurve);
        for (std::size_t channel = 0; channel < 3; ++channel)
            picture.pixels[i + channel] = static_cast<float>(shown[channel]);
    }
    return {path, std::move(picture), std::move(attributes), {}};
}

int runDenoise(const DenoiseRequest& request)
{
    io::checkOutputsCanBeWritten({{request.output, io::OutputKind::Image}});
    film::RenderFile render;
    try {
        render = film::readRenderFile(request.input);
    } catch (const std::exception& error) {
        throw std::runtime_error(std::string("cannot denoise: ") + error.what());
    }
    const auto start = std::chrono::steady_clock::now();
    const io::Image denoised = denoisedRadiance(render.accumulation);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    io::writeAllOrNothing(
        {denoisedOutput(request.output, denoised, render.metadata, request.input)});
    char line[256];
    std::snprintf(line, sizeof line, "denoised %s (%dx%d, %lld spp) in %.2f s -> ",
                  request.input.string().c_str(), render.metadata.width, render.metadata.height,
                  static_cast<long long>(render.metadata.samplesPerPixel), seconds);
    std::cout << line << request.output.string() << std::endl;
    return kExitSuccess;
}

}  // namespace app
