#include "app/MergeCommand.h"

#include "app/RenderCommand.h"
#include "app/RenderOutputs.h"
#include "film/RenderFile.h"
#include "io/OutputFiles.h"
#include "platform/ContextFactory.h"
#include "render/AccumulationTargets.h"
#include "render/ToneMapper.h"
#include "scene/FileLookup.h"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <stdexcept>

namespace app {

namespace fs = std::filesystem;

namespace {

void refuseOutputsInOneFile(const MergeRequest& request)
{
    std::vector<std::pair<const char*, fs::path>> outputs = {{"OUT", request.output}};
    if (request.picture)
        outputs.push_back({"--png", *request.picture});
    if (request.statisticsOutput)
        outputs.push_back({"--stats-output", *request.statisticsOutput});
    for (std::size_t i = 0; i < outputs.size(); ++i)
        for (std::size_t j = i + 1; j < outputs.size(); ++j)
            if (io::resolveToSameFile(outputs[i].second, outputs[j].second))
                throw UsageError(std::string(outputs[j].first) + " " + outputs[j].second.string() +
                                 " names the same file as " + outputs[i].first + " " +
                                 outputs[i].second.string() + ": give different files");
}

// Why the inputs cannot be merged, if they cannot: they must estimate one image (size,
// scene, camera, settings, program build), and hold no sample twice.
void refuseMismatches(const std::vector<fs::path>& paths,
                      const std::vector<film::RenderFile>& renders)
{
    const film::RenderMetadata& first = renders.front().metadata;
    for (std::size_t i = 1; i < renders.size(); ++i)
        if (const auto difference = film::imageDifference(first, renders[i].metadata))
            throw std::runtime_error("cannot merge " + paths[0].string() + " and " +
                                     paths[i].string() + ": they differ in " + difference->what +
                                     ": " + difference->first + " and " + difference->second +
                                     ", so their samples estimate different images");
    for (std::size_t i = 0; i < renders.size(); ++i)
        for (std::size_t j = i + 1; j < renders.size(); ++j) {
            // Crops that share no pixel share no sample, whatever their seeds.
            const auto& a = renders[i].metadata.crop;
            const auto& b = renders[j].metadata.crop;
            if (a && b && a->disjointFrom(*b))
                continue;
            if (const auto overlap = film::firstOverlap(renders[i].metadata.sampleRanges,
                                                        renders[j].metadata.sampleRanges))
                throw std::runtime_error(
                    "cannot merge " + paths[i].string() + " and " + paths[j].string() +
                    ": both hold samples of seed " + std::to_string(overlap->first.seed) +
                    " with the same indices (" + film::describeSampleRange(overlap->first) + "; " +
                    film::describeSampleRange(overlap->second) +
                    "), the same paths twice: render shards with different --seed" +
                    (a || b ? std::string(", or crops (--crop) that share no pixel") : ""));
        }
}

// The rectangle holding every pixel the inputs traced (an input without a crop, the whole
// frame); nothing where that is the whole frame.
std::optional<film::PixelCrop> mergedCrop(const std::vector<film::RenderFile>& renders)
{
    const film::RenderMetadata& first = renders.front().metadata;
    const film::PixelCrop frame{0, 0, first.width, first.height};
    film::PixelCrop bounds = first.crop.value_or(frame);
    for (const film::RenderFile& render : renders) {
        const film::PixelCrop crop = render.metadata.crop.value_or(frame);
        bounds = {std::min(bounds.x0, crop.x0), std::min(bounds.y0, crop.y0),
                  std::max(bounds.x1, crop.x1), std::max(bounds.y1, crop.y1)};
    }
    if (bounds == frame)
        return std::nullopt;
    return bounds;
}

void refuseInexactCounts(const film::Accumulation& merged)
{
    for (int y = 0; y < merged.height(); ++y)
        for (int x = 0; x < merged.width(); ++x)
            if (merged.samplesTaken(x, y) > static_cast<double>(film::kLargestSampleCount))
                throw std::runtime_error(
                    "cannot merge: a pixel would hold more than 16777216 samples, beyond what "
                    "the 32-bit float counts hold exactly");
}

film::RenderMetadata mergedMetadata(const std::vector<fs::path>& paths,
                                    const std::vector<film::RenderFile>& renders)
{
    film::RenderMetadata merged = renders.front().metadata;
    merged.samplesPerPixel = 0;
    merged.renderSeconds = 0.0;
    merged.interrupted.clear();
    merged.mergedFrom.clear();
    std::vector<film::SampleRange> ranges;
    for (std::size_t i = 0; i < renders.size(); ++i) {
        const film::RenderMetadata& input = renders[i].metadata;
        // Each input's count is at most kLargestSampleCount (RenderMetadata.h): the 64-bit sum
        // cannot wrap before it is checked.
        merged.samplesPerPixel += input.samplesPerPixel;
        if (merged.samplesPerPixel > film::kLargestSampleCount)
            throw std::runtime_error(
                "cannot merge: the inputs hold " + std::to_string(merged.samplesPerPixel) +
                " samples per pixel from " + paths[0].string() + " to " + paths[i].string() +
                ", more than the " + std::to_string(film::kLargestSampleCount) +
                " a pixel can hold (its 32-bit float counts are exact up to there)");
        merged.renderSeconds += input.renderSeconds;
        ranges.insert(ranges.end(), input.sampleRanges.begin(), input.sampleRanges.end());
        merged.mergedFrom.push_back(paths[i].string());
        if (i > 0)
            film::addRenderingDevice(merged, input);
        if (!input.interrupted.empty())
            merged.interrupted += (merged.interrupted.empty() ? "" : "; ") + paths[i].string() +
                                  ": " + input.interrupted;
    }
    merged.sampleRanges = film::normalizedRanges(ranges);
    return merged;
}

// The tone-mapped picture, by the renderer's own display pass in a headless context, at the
// exposure and by the curve the inputs record (they are one render's: all alike).
io::Image toneMappedPicture(const film::Accumulation& accumulation,
                            const settings::RenderSettings& settings)
{
    platform::ContextRequest request;
    request.headless = true;
    const auto context = platform::createContext(request);
    const render::AccumulationTargets targets(accumulation);
    const render::ToneMapper toneMapper(scene::FileLookup::dataDirectory() / "shaders");
    const gl::VertexArray triangle;
    return toneMapper.render(targets.previous().estimate, accumulation.width(),
                             accumulation.height(), triangle, settings.exposure,
                             settings.toneCurve);
}

}  // namespace

int runMerge(const MergeRequest& request, const InterruptWatch& interrupt)
{
    refuseOutputsInOneFile(request);
    std::vector<io::OutputRequest> outputs = {{request.output, io::OutputKind::Image}};
    if (request.picture)
        outputs.push_back({*request.picture, io::OutputKind::Image});
    if (request.statisticsOutput)
        outputs.push_back({*request.statisticsOutput, io::OutputKind::Statistics});
    io::checkOutputsCanBeWritten(outputs);
    std::vector<fs::path> outputPaths;
    for (const io::OutputRequest& output : outputs)
        outputPaths.push_back(output.path);
    removeStaleTemporariesOf(outputPaths);

    std::vector<film::RenderFile> renders;
    for (const fs::path& input : request.inputs) {
        try {
            renders.push_back(film::readRenderFile(input));
        } catch (const std::exception& error) {
            throw std::runtime_error(std::string("cannot merge: ") + error.what());
        }
    }
    refuseMismatches(request.inputs, renders);

    std::vector<const film::Accumulation*> parts;
    for (const film::RenderFile& render : renders)
        parts.push_back(&render.accumulation);
    const film::Accumulation merged = film::combineAccumulations(parts);
    // Feature buffers survive a merge only where every input has them.
    for (std::size_t i = 0; i < renders.size() && !merged.hasFeatures(); ++i)
        if (renders[i].accumulation.hasFeatures()) {
            std::cout << "merge: note: not every input has feature buffers (" +
                             request.inputs[i].string() + " has): the merged file keeps none"
                      << std::endl;
            break;
        }
    refuseInexactCounts(merged);
    film::RenderMetadata metadata = mergedMetadata(request.inputs, renders);
    // Crops hold their samples in their own pixels, not on top of each other's: what a pixel
    // of the merge holds is the most of any.
    const bool anyCrop = std::any_of(renders.begin(), renders.end(), [](const auto& render) {
        return render.metadata.crop.has_value();
    });
    if (anyCrop) {
        metadata.samplesPerPixel = film::samplesTakenSpan(merged).most;
        metadata.crop = mergedCrop(renders);
    }

    std::vector<fs::path> images = {request.output};
    if (request.picture)
        images.push_back(*request.picture);
    if (interrupt.requested()) {
        std::cout << "merge interrupted before its files were written: nothing written"
                  << std::endl;
        return kExitInterrupted;
    }
    io::writeAllOrNothing(renderOutputs(images, request.statisticsOutput, merged, metadata, [&] {
        return toneMappedPicture(merged, metadata.settings);
    }));

    char numbers[160];
    std::snprintf(numbers, sizeof numbers, "%dx%d, %lld spp", metadata.width, metadata.height,
                  static_cast<long long>(metadata.samplesPerPixel));
    char seconds[64];
    std::snprintf(seconds, sizeof seconds, "%.2f s of rendering", metadata.renderSeconds);
    std::string line = "merged " + std::to_string(renders.size()) + " renders: " + numbers +
                       " (seeds " + film::describeSeeds(metadata.sampleRanges) + "), " + seconds +
                       " -> " + request.output.string();
    for (std::size_t i = 1; i < images.size(); ++i)
        line += " and " + images[i].string();
    if (request.statisticsOutput)
        line += " and " + request.statisticsOutput->string();
    std::cout << line << std::endl;
    return kExitSuccess;
}

}  // namespace app
