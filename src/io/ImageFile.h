#pragma once
#include "io/Image.h"

#include <filesystem>

namespace io {

// True for files that hold linear radiance (.exr, .pfm, .hdr); the rest hold pictures.
bool holdsLinearRadiance(const std::filesystem::path& path);

// Writes `image` through OpenImageIO in the format the extension names. Values are written
// as given: linear radiance for HDR formats, display values in [0, 1] for the others (8-bit).
// The file appears complete or not at all: it is written under a temporary name in the same
// folder and renamed. Throws std::runtime_error naming the file on failure.
void writeImage(const std::filesystem::path& path, const Image& image);

// Throws std::runtime_error unless OpenImageIO can write the format `path`'s extension names.
void checkWritableFormat(const std::filesystem::path& path);

// Throws std::runtime_error naming the file unless OpenImageIO can open it as an image (its
// header is read, not its pixels).
void checkReadableImage(const std::filesystem::path& path);

// Reads any format OpenImageIO knows as float RGB(A) (8-bit data scaled to [0, 1]).
Image readImage(const std::filesystem::path& path);

}  // namespace io
