// The libFuzzer entry point for the readers of the render's EXR files (tests/README.md,
// "Fuzzing"). The input is written to a file named .exr and read as `info` reads a file, then
// as merge and --resume read one. A refusal (std::runtime_error) is the expected outcome of a
// bad input; anything else (a crash, a sanitizer report, another exception, an allocation
// beyond libFuzzer's limit, a hang) is a finding, and so is a file accepted whose values break
// what the readers promise: a count beyond the largest, or a merge of it that is not finite.
#include "film/Accumulation.h"
#include "film/RenderFile.h"
#include "film/RenderFileChecks.h"
#include "film/RenderMetadata.h"
#include "io/ImageFile.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;

// One file per process, written afresh for each input.
const fs::path& inputFile()
{
    static const fs::path file = [] {
        const fs::path folder = fs::temp_directory_path() /
                                ("raytracer-render-file-fuzz-" + std::to_string(::getpid()));
        fs::create_directories(folder);
        return folder / "input.exr";
    }();
    return file;
}

bool allFinite(const io::Image& image)
{
    for (float value : image.pixels)
        if (!std::isfinite(value))
            return false;
    return true;
}

void readAsInfoDoes(const fs::path& file)
{
    const io::ImageFileContents contents = io::readImageFile(file);
    const auto metadata = film::metadataFromAttributes(contents.attributes, file.string());
    if (!metadata)
        return;
    film::checkPixelValues(contents, *metadata, file.string());
    film::checkPixelDigest(contents, file.string());
    film::describeSeeds(metadata->sampleRanges);
    film::describeProgram(*metadata);
}

void readAsMergeAndResumeDo(const fs::path& file)
{
    const film::RenderFile render = film::readRenderFile(file);
    const film::Accumulation& accumulation = render.accumulation;
    const film::SampleCountSpan span = film::samplesTakenSpan(accumulation);
    if (span.fewest < 0 || span.most > film::kLargestSampleCount || span.fewest > span.most)
        std::abort();
    // A merge of it with itself (counts within the largest) is all finite.
    if (2 * static_cast<std::int64_t>(span.most) <= film::kLargestSampleCount) {
        const film::Accumulation merged =
            film::combineAccumulations({&accumulation, &accumulation});
        if (!allFinite(merged.estimate) || !allFinite(merged.moments))
            std::abort();
    }
    if (film::imageDifference(render.metadata, render.metadata))
        std::abort();
    film::metadataAttributes(render.metadata);
    film::sampleStatistics(accumulation);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    {
        std::ofstream file(inputFile(), std::ios::binary | std::ios::trunc);
        file.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    }
    try {
        readAsInfoDoes(inputFile());
    } catch (const std::runtime_error&) {
    }
    try {
        readAsMergeAndResumeDo(inputFile());
    } catch (const std::runtime_error&) {
    }
    return 0;
}
