#pragma once
#include "io/Image.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace io {

// A metadata attribute written into the image file's header where its format holds named
// attributes (EXR, PNG; PPM, PFM and TIFF drop them). Text for now; typed values can join it.
struct ImageAttribute {
    std::string name;
    std::string value;
};

// True for files that hold linear radiance (.exr, .pfm, .hdr); the rest hold pictures.
bool holdsLinearRadiance(const std::filesystem::path& path);

// Writes `image` to `path` in the format the extension names (io/ImageFormats.h). Values are
// written as given: linear radiance for HDR formats, display values in [0, 1] for the others
// (8-bit). The file appears complete or not at all (io/OutputFiles.h). Throws
// std::runtime_error naming the file and the reason on failure.
void writeImage(const std::filesystem::path& path, const Image& image,
                const std::vector<ImageAttribute>& attributes = {});

// Writes `image` into `file` in the format `destination`'s extension names; messages name
// `destination` (the user's path) even where `file` is its temporary stand-in.
// `channelNames`, where the format names channels (EXR): one per channel; empty, the
// format's default (R, G, B, A).
void writeImageFile(const std::filesystem::path& file, const std::filesystem::path& destination,
                    const Image& image, const std::vector<ImageAttribute>& attributes,
                    const std::vector<std::string>& channelNames = {});

// Throws std::runtime_error naming the file unless OpenImageIO can open it as an image (its
// header is read, not its pixels).
void checkReadableImage(const std::filesystem::path& path);

// What an image file's header says of its size, read without its pixels: so that a reader
// can refuse a file too large to hold before allocating for it.
struct ImageSize {
    int width = 0;
    int height = 0;
    int channels = 0;
};
// Throws std::runtime_error naming the file and the reason when it cannot be opened.
ImageSize readImageSize(const std::filesystem::path& path);

// The value of the metadata attribute `name` in the image file, as text; nothing when the
// file has no such attribute (or its format holds none). Throws when the file is unreadable.
std::optional<std::string> readImageAttribute(const std::filesystem::path& path,
                                              const std::string& name);

// Reads any format OpenImageIO knows as float RGB(A) (8-bit data scaled to [0, 1]).
Image readImage(const std::filesystem::path& path);

// An image file as it is: every channel in the file's order with its name, and every
// attribute of its header as text.
struct ImageFileContents {
    Image image;
    std::vector<std::string> channelNames;
    std::vector<ImageAttribute> attributes;
    std::string format;  // OpenImageIO's name for it: "openexr", "png", ...

    // The index of the channel called `name`, or -1.
    int channelIndex(const std::string& name) const;
};
// Throws std::runtime_error naming the file and the reason when it cannot be read.
ImageFileContents readImageFile(const std::filesystem::path& path);

}  // namespace io
