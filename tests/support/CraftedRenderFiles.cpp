#include "support/CraftedRenderFiles.h"

#include "film/RenderFileChecks.h"
#include "io/OutputFiles.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <stdexcept>

namespace testing_support {

namespace fs = std::filesystem;

namespace {

std::vector<unsigned char> bytesOf(const fs::path& path)
{
    std::ifstream file(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

void writeBytes(const fs::path& path, const std::vector<unsigned char>& bytes)
{
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    file.write(reinterpret_cast<const char*>(bytes.data()),
               static_cast<std::streamsize>(bytes.size()));
    if (!file)
        throw std::runtime_error("cannot write " + path.string());
}

std::uint32_t read32(const std::vector<unsigned char>& bytes, std::size_t at)
{
    std::uint32_t value = 0;
    for (int i = 3; i >= 0; --i)
        value = (value << 8) | bytes.at(at + i);
    return value;
}

std::uint64_t read64(const std::vector<unsigned char>& bytes, std::size_t at)
{
    return read32(bytes, at) | (static_cast<std::uint64_t>(read32(bytes, at + 4)) << 32);
}

void write32(std::vector<unsigned char>& bytes, std::size_t at, std::uint32_t value)
{
    for (int i = 0; i < 4; ++i)
        bytes.at(at + i) = static_cast<unsigned char>(value >> (8 * i));
}

void write64(std::vector<unsigned char>& bytes, std::size_t at, std::uint64_t value)
{
    write32(bytes, at, static_cast<std::uint32_t>(value));
    write32(bytes, at + 4, static_cast<std::uint32_t>(value >> 32));
}

// Where a single-part scan-line OpenEXR file keeps what the data-window cases change: the
// values of its dataWindow and displayWindow attributes (box2i: four int32), and its table of
// chunk offsets, which follows the header (OpenEXR's file layout: magic, version, attributes
// as name, type, size, value, an empty name, then the offsets).
struct ExrLayout {
    std::size_t dataWindow = 0;
    std::size_t displayWindow = 0;
    std::size_t offsetTable = 0;
    int linesPerChunk = 1;
};

ExrLayout layoutOf(const std::vector<unsigned char>& bytes)
{
    auto text = [&](std::size_t& at) {
        const std::size_t start = at;
        while (bytes.at(at) != 0)
            ++at;
        return std::string(bytes.begin() + start, bytes.begin() + at++);
    };
    ExrLayout layout;
    std::size_t at = 8;
    for (std::string name; !(name = text(at)).empty();) {
        text(at);  // the type
        const std::uint32_t size = read32(bytes, at);
        at += 4;
        if (name == "dataWindow")
            layout.dataWindow = at;
        else if (name == "displayWindow")
            layout.displayWindow = at;
        else if (name == "compression") {
            // NONE RLE ZIPS ZIP PIZ PXR24 B44 B44A DWAA DWAB
            const int lines[] = {1, 1, 1, 16, 32, 16, 32, 32, 32, 256};
            layout.linesPerChunk = lines[std::min<int>(bytes.at(at), 9)];
        }
        at += size;
    }
    layout.offsetTable = at;
    return layout;
}

// The header says width x height, and the table of chunk offsets is made as long as that
// needs (its new entries point at the last chunk), so that the file opens; then the file is
// padded to `fileSize` bytes. What the header asks for is far more than the file holds.
std::function<void(std::vector<unsigned char>&)> dataWindow(int width, int height,
                                                            std::size_t fileSize)
{
    return [=](std::vector<unsigned char>& bytes) {
        const ExrLayout layout = layoutOf(bytes);
        const int oldHeight = static_cast<int>(read32(bytes, layout.dataWindow + 12)) -
                              static_cast<int>(read32(bytes, layout.dataWindow + 4)) + 1;
        const int lines = layout.linesPerChunk;
        const std::size_t oldChunks = (oldHeight + lines - 1) / lines;
        const std::size_t newChunks = (height + lines - 1) / lines;
        for (std::size_t window : {layout.dataWindow, layout.displayWindow}) {
            write32(bytes, window, 0);
            write32(bytes, window + 4, 0);
            write32(bytes, window + 8, static_cast<std::uint32_t>(width - 1));
            write32(bytes, window + 12, static_cast<std::uint32_t>(height - 1));
        }
        const std::size_t added = (newChunks - oldChunks) * 8;
        std::vector<std::uint64_t> offsets;
        for (std::size_t i = 0; i < oldChunks; ++i)
            offsets.push_back(read64(bytes, layout.offsetTable + 8 * i) + added);
        while (offsets.size() < newChunks)
            offsets.push_back(offsets.back());
        bytes.insert(bytes.begin() + layout.offsetTable + oldChunks * 8, added, 0);
        for (std::size_t i = 0; i < offsets.size(); ++i)
            write64(bytes, layout.offsetTable + 8 * i, offsets[i]);
        if (bytes.size() < fileSize)
            bytes.resize(fileSize, 0);
    };
}

// The size of the attribute `name` (a string) made `size`: OpenEXR allocated that much before
// it found the file too short (the fuzz target's first finding).
std::function<void(std::vector<unsigned char>&)> attributeSize(const std::string& name,
                                                               std::uint32_t size)
{
    return [=](std::vector<unsigned char>& bytes) {
        const std::string entry = name + std::string(1, '\0') + "string" + std::string(1, '\0');
        const auto found = std::search(bytes.begin(), bytes.end(), entry.begin(), entry.end());
        if (found == bytes.end())
            throw std::logic_error("the base file has no attribute " + name);
        write32(bytes, static_cast<std::size_t>(found - bytes.begin()) + entry.size(), size);
    };
}

// One bit of the pixel data changed near the file's end (in its last chunk).
void flipAByteOfThePixels(std::vector<unsigned char>& bytes)
{
    bytes.at(bytes.size() - 2) ^= 0x01;
}

std::function<void(io::ImageFileContents&)> setValue(const std::string& channel, float value)
{
    return [=](io::ImageFileContents& file) { craftedValue(file, channel) = value; };
}

std::function<void(io::ImageFileContents&)> setAttributeTo(const std::string& name,
                                                           const std::string& value)
{
    return [=](io::ImageFileContents& file) { setAttribute(file, name, value); };
}

}  // namespace

float& craftedValue(io::ImageFileContents& file, const std::string& channel)
{
    const int index = file.channelIndex(channel);
    if (index < 0)
        throw std::logic_error("the base file has no channel " + channel);
    return file.image.at(kCraftedPixelX, kCraftedPixelY, index);
}

void setAttribute(io::ImageFileContents& file, const std::string& name, const std::string& value)
{
    const auto found = std::find_if(file.attributes.begin(), file.attributes.end(),
                                    [&](const io::ImageAttribute& a) { return a.name == name; });
    if (found != file.attributes.end())
        found->value = value;
    else
        file.attributes.push_back({name, value});
}

const std::vector<CraftedRenderFile>& craftedRenderFiles()
{
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float infinity = std::numeric_limits<float>::infinity();
    static const std::vector<CraftedRenderFile> files = {
        {"negative-count",
         "pixel (3, 2), channel samples: -3 is not a number of samples",
         setValue("samples", -3.0f),
         "",
         {}},
        {"fractional-count",
         "pixel (3, 2), channel samples: 2.5 is not a number of samples",
         setValue("samples", 2.5f),
         "",
         {}},
        {"nan-count",
         "pixel (3, 2), channel samples: nan is not a number of samples",
         setValue("samples", nan),
         "",
         {}},
        // Through lround into an int it wrapped, and --resume rendered for ever.
        {"count-of-a-trillion",
         "pixel (3, 2), channel samples: 9.99999996e+11 makes the pixel hold",
         setValue("samples", 1e12f),
         "",
         {}},
        {"negative-discarded-count",
         "pixel (3, 2), channel samplesDiscarded: -1 is not a number of samples",
         setValue("samplesDiscarded", -1.0f),
         "",
         {}},
        {"nan-mean",
         "pixel (3, 2), channel R: nan is not a mean radiance",
         setValue("R", nan),
         "",
         {}},
        {"infinite-mean",
         "pixel (3, 2), channel G: inf is not a mean radiance",
         setValue("G", infinity),
         "",
         {}},
        {"negative-mean",
         "pixel (3, 2), channel B: -0.5 is not a mean radiance",
         setValue("B", -0.5f),
         "",
         {}},
        // Its square made the merged second moments infinite.
        {"mean-of-3.4e38",
         "pixel (3, 2), channel R: 3.39999995e+38 is not a mean radiance",
         setValue("R", 3.4e38f),
         "",
         {}},
        {"negative-second-moment",
         "pixel (3, 2), channel sumSquaredDeviations.G: -1 is not a sum of squared deviations",
         setValue("sumSquaredDeviations.G", -1.0f),
         "",
         {}},
        {"second-moment-beyond-its-mean",
         "pixel (3, 2), channel sumSquaredDeviations.R: 1.00000002e+30 is more than",
         setValue("sumSquaredDeviations.R", 1e30f),
         "",
         {}},
        {"mean-without-a-sample",
         "pixel (3, 2), channel R: 0.25 is the mean of no sample",
         [](io::ImageFileContents& file) {
             craftedValue(file, "samplesDiscarded") += craftedValue(file, "samples");
             craftedValue(file, "samples") = 0.0f;
             craftedValue(file, "R") = 0.25f;
         },
         "",
         {}},
        // Summed in an int over two shards it wrapped to -2 samples per pixel.
        {"samples-per-pixel-2147483647",
         "raytracer:samplesPerPixel is '2147483647', not a count from 0 to 16777216",
         setAttributeTo("raytracer:samplesPerPixel", "2147483647"),
         "",
         {}},
        {"sample-range-beyond-any-pixel",
         "raytracer:sampleRanges holds 4294967296 samples of seed 1 from index 0, beyond the "
         "16777216 samples a pixel can hold",
         setAttributeTo("raytracer:sampleRanges", "1:0+4294967296"),
         "",
         {}},
        {"render-seconds-nan",
         "raytracer:renderSeconds is 'nan', not a number of seconds",
         setAttributeTo("raytracer:renderSeconds", "nan"),
         "",
         {}},
        // A bit of the stored data changed, in each of three compressions (B44 stores 32-bit
        // floats as they are, so the value changed is one a render could hold).
        {"rle-byte-flipped", "rle-byte-flipped.exr", {}, "rle", flipAByteOfThePixels},
        {"piz-byte-flipped", "piz-byte-flipped.exr", {}, "piz", flipAByteOfThePixels},
        {"b44-byte-flipped",
         "b44-byte-flipped.exr: its pixels are not the ones it was written",
         {},
         "b44",
         flipAByteOfThePixels},
        // The header of a 10000x10000 image (3.2 GB of pixels) in a file of 20 KB.
        {"data-window-10000x10000-in-20-kb",
         "its size, 10000x10000, is beyond the largest image read (33554432 pixels)",
         {},
         "",
         dataWindow(10000, 10000, 20000)},
        // An attribute of 1.9 GB in a file of 3 KB.
        {"attribute-of-1.9-gb",
         "Attribute 'raytracer:camera', type 'string': Invalid size 1885430528",
         {},
         "",
         attributeSize("raytracer:camera", 1885430528u)},
        // Within the largest image, but 512 MB of pixels from 20 KB.
        {"data-window-4000x4000-in-20-kb",
         "asks for 512000000 bytes of pixels (4000x4000) from a file of 20000 bytes",
         {},
         "",
         dataWindow(4000, 4000, 20000)},
    };
    return files;
}

const CraftedRenderFile& craftedRenderFile(const std::string& name)
{
    for (const CraftedRenderFile& file : craftedRenderFiles())
        if (file.name == name)
            return file;
    throw std::logic_error("no crafted render file " + name);
}

void writeCraftedRenderFile(const CraftedRenderFile& crafted, const fs::path& base,
                            const fs::path& path)
{
    io::ImageFileContents contents = io::readImageFile(base);
    const bool hadDigest = std::any_of(
        contents.attributes.begin(), contents.attributes.end(),
        [](const io::ImageAttribute& a) { return a.name == film::kPixelDigestAttribute; });
    if (crafted.editContents) {
        crafted.editContents(contents);
        if (hadDigest)
            setAttribute(contents, film::kPixelDigestAttribute,
                         film::pixelDigest(contents.image, contents.channelNames));
    }
    // The program's own attributes; the format's own (compression, windows) are the writer's.
    std::vector<io::ImageAttribute> attributes;
    for (const io::ImageAttribute& attribute : contents.attributes)
        if (attribute.name.rfind("raytracer:", 0) == 0)
            attributes.push_back(attribute);
    if (!crafted.compression.empty())
        attributes.push_back({"compression", crafted.compression});
    io::writeAllOrNothing({{path, contents.image, attributes, contents.channelNames}});
    if (crafted.editBytes) {
        std::vector<unsigned char> bytes = bytesOf(path);
        crafted.editBytes(bytes);
        writeBytes(path, bytes);
    }
}

}  // namespace testing_support
