#pragma once
// The render's own files: what an EXR written with --output holds, so that renders can be
// merged and resumed, and the statistics file.
//
// The EXR holds the radiance (R, G, B: the mean of the samples kept) and, per pixel, what
// combining it with other samples needs (film/Accumulation.h), each channel named for what
// it is:
//   R G B  samples  samplesDiscarded  sumSquaredDeviations.R  .G  .B
// with the metadata (film/RenderMetadata.h) in its header. A viewer shows R, G, B; the
// rest is a layer beside them. The statistics file holds
//   samples  samplesDiscarded  varianceOfMean
// (varianceOfMean: the channel average of the variance of the mean radiance).
#include "io/OutputFiles.h"
#include "film/Accumulation.h"
#include "film/RenderMetadata.h"

#include <filesystem>
#include <string>
#include <vector>

namespace film {

const std::vector<std::string>& accumulationChannelNames();
const std::vector<std::string>& statisticsChannelNames();

// The EXR of a render: radiance, accumulation and metadata.
io::OutputImage accumulationOutput(const std::filesystem::path& path,
                                   const Accumulation& accumulation,
                                   const RenderMetadata& metadata);
// The statistics file, with the metadata where the format holds it.
io::OutputImage statisticsOutput(const std::filesystem::path& path,
                                 const Accumulation& accumulation,
                                 const RenderMetadata& metadata);

struct RenderFile {
    Accumulation accumulation;
    RenderMetadata metadata;  // its width and height the image's
};

// Reads an EXR written by accumulationOutput. Throws std::runtime_error with a one-line
// reason naming the file when it cannot be read, holds no accumulation (a picture, a PFM,
// an EXR of another program) or no metadata of this program.
RenderFile readRenderFile(const std::filesystem::path& path);

}  // namespace film
