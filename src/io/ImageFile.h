#pragma once
// Image files in and out. Files read are untrusted (a merge's inputs come from other machines,
// a resumed render from a disk that filled, a download): only a regular file is opened, only by
// the reader of the format its extension names, and its header is held to the limits below
// before a pixel is allocated. Files written are encoded in memory and written by the program
// itself (io/OutputFiles.h), so that no library can lose a write error or end the process.
#include "io/Image.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace io {

// The largest image the program reads (docs/USAGE.md, "Files from elsewhere"), checked against
// the header before anything is allocated for its pixels:
// - no side above 65536 (the command line's limit) and at most 2^25 pixels (33.5 million:
//   8K UHD, 7680x4320, is within it), with at most 16 channels: 2 GiB of 32-bit floats;
// - at most 4096 bytes of pixels for each byte of the file: the lossless compressions of
//   OpenEXR, PNG and TIFF stop near 1032:1 (deflate's limit) even on an image of one value,
//   so a header that asks more of a small file describes pixels the file cannot hold.
inline constexpr int kLargestSideRead = 65536;
inline constexpr std::int64_t kLargestPixelCountRead = std::int64_t(1) << 25;
inline constexpr int kLargestChannelCountRead = 16;
inline constexpr std::int64_t kLargestExpansionRead = 4096;
// A tiled file's tiles are read one at a time, whole: at most 1024 pixels a side (OpenEXR's
// own are 32 to 256).
inline constexpr int kLargestTileSideRead = 1024;

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

// The bytes of the file `destination` would hold: `image` encoded in memory in the format
// its extension names, with `attributes` where the format holds them. `channelNames`, where
// the format names channels (EXR): one per channel; empty, the format's default (R, G, B, A).
// Throws std::runtime_error naming `destination` when the format cannot hold the image.
std::vector<unsigned char> encodeImage(const std::filesystem::path& destination, const Image& image,
                                       const std::vector<ImageAttribute>& attributes,
                                       const std::vector<std::string>& channelNames = {});

// Throws std::runtime_error naming the file unless it is a regular file that OpenImageIO
// can open as an image (its header is read, not its pixels). For textures, whose formats are
// OpenImageIO's to recognise.
void checkReadableImage(const std::filesystem::path& path);

// What a file's header says of its image.
struct ImageHeader {
    int width = 0;
    int height = 0;
    int channels = 0;
    std::string format;  // OpenImageIO's name for it: "openexr", "png", ...
};
// The header of an image file read as the format its extension names, within the limits
// above. Throws std::runtime_error naming the file and the reason when it is not a regular
// file, cannot be read or is beyond the limits.
ImageHeader readImageHeader(const std::filesystem::path& path);

// The value of the metadata attribute `name` in the image file, as text; nothing when the
// file has no such attribute (or its format holds none). Throws as readImageHeader.
std::optional<std::string> readImageAttribute(const std::filesystem::path& path,
                                              const std::string& name);

// Reads the image as float RGB(A) (8-bit data scaled to [0, 1]). Throws as readImageFile.
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
// Reads a regular file as the format its extension names (one of io/ImageFormats.h; no other
// reader is tried), its header checked against the limits above before its pixels are
// allocated. Throws std::runtime_error naming the file and the reason when it cannot be read.
ImageFileContents readImageFile(const std::filesystem::path& path);

}  // namespace io
