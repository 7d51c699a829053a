#pragma once
// Final frames denoised by Open Image Denoise (film/Denoiser.h): --denoise writes each output
// denoised beside the raw one, and `raytracer denoise IN.exr OUT` denoises a finished or
// merged render. The denoised image is biased (docs/DENOISING.md): it never replaces the raw
// one, holds no accumulation (it cannot be merged or resumed), and says what it is in its
// metadata (attribute raytracer:denoised).
#include "app/CommandLine.h"
#include "film/Accumulation.h"
#include "film/RenderMetadata.h"
#include "io/OutputFiles.h"

#include <filesystem>
#include <vector>

namespace app {

// NAME.denoised.EXT beside NAME.EXT.
std::filesystem::path denoisedPath(const std::filesystem::path& output);

// The accumulation's radiance denoised, guided by its albedo and normal. Throws
// std::runtime_error when it has no feature buffers, film::DenoiserUnavailable without OIDN.
io::Image denoisedRadiance(const film::Accumulation& accumulation);

// `denoised` written to `path`: linear radiance (R, G, B) in an .exr, .pfm or .hdr, the
// picture tone-mapped at the exposure and by the curve `metadata` records otherwise; with `metadata` and a raytracer:denoised
// attribute naming the library and `rawFile`, the image it was denoised from.
io::OutputImage denoisedOutput(const std::filesystem::path& path, const io::Image& denoised,
                               const film::RenderMetadata& metadata,
                               const std::filesystem::path& rawFile);

// raytracer denoise IN.exr OUT; returns the exit status.
int runDenoise(const DenoiseRequest& request);

}  // namespace app
