#pragma once
// The render's own files: what an EXR written with --output holds, so that renders can be
// merged and resumed, and the statistics file.
//
// The EXR holds the radiance (R, G, B: the mean of the samples kept) and, per pixel, what
// combining it with other samples needs (film/Accumulation.h), each channel named for what
// it is:
//   R G B  samples  samplesDiscarded  sumSquaredDeviations.R  .G  .B
// and, where the render kept feature buffers (--feature-buffers, Accumulation.h),
//   albedo.R .G .B  N.X .Y .Z  Z  coverage
// (the first-hit albedo, world-space normal, camera distance and the fraction of samples whose
// camera ray hit something), with the metadata (film/RenderMetadata.h) in its header. A viewer
// shows R, G, B; the rest are layers beside them. The statistics file holds
//   samples  samplesDiscarded  varianceOfMean
// (varianceOfMean: the channel average of the variance of the mean radiance).
#include "film/Accumulation.h"
#include "film/RenderMetadata.h"
#include "io/OutputFiles.h"

#include <filesystem>
#include <string>
#include <vector>

namespace film {

const std::vector<std::string>& accumulationChannelNames();
const std::vector<std::string>& statisticsChannelNames();
// The feature buffers' channels, in Accumulation's order: albedoDepth's r, g, b, then
// normalCoverage's r, g, b, then albedoDepth's a (Z), normalCoverage's a (coverage).
const std::vector<std::string>& featureChannelNames();

// The EXR of a render: radiance, accumulation and metadata, and the SHA-256 of its pixels
// (film/RenderFileChecks.h).
io::OutputImage accumulationOutput(const std::filesystem::path& path,
                                   const Accumulation& accumulation,
                                   const RenderMetadata& metadata);
// The statistics file, with the metadata where the format holds it.
io::OutputImage statisticsOutput(const std::filesystem::path& path,
                                 const Accumulation& accumulation, const RenderMetadata& metadata);

struct RenderFile {
    Accumulation accumulation;
    RenderMetadata metadata;  // its width and height the image's
};

// Reads an EXR written by accumulationOutput, as untrusted: only a regular file named .exr,
// only by OpenEXR's reader, its size within io/ImageFile.h's limits, its metadata within
// what a render holds, every pixel's values checked and, where it says what its pixels were
// (raytracer:pixelSha256), that too (film/RenderFileChecks.h). Throws std::runtime_error
// with a one-line reason naming the file (and the first pixel and channel at fault) when it
// cannot be read, holds no accumulation (a picture, a PFM, an EXR of another program), no
// metadata of this program, or a value no render holds.
RenderFile readRenderFile(const std::filesystem::path& path);

}  // namespace film
