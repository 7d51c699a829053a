#pragma once
// What a render's file must hold before merge, --resume or info uses it (docs/USAGE.md, "Files
// from elsewhere"). The file may come from another machine, a disk that filled, a copy that
// went wrong or someone who made it up, so every value of every pixel is checked against what
// a render can hold, and the first that no render holds is reported with its pixel and
// channel.
#include "film/RenderMetadata.h"
#include "io/ImageFile.h"

#include <string>
#include <vector>

namespace film {

// The largest mean radiance a pixel may hold, 2^39 (5.5e11): with at most kLargestSampleCount
// samples, a second moment within its bound below stays under 2^127, within a 32-bit float, in
// the file, on the GPU that goes on accumulating and in a merge.
inline constexpr double kLargestMeanRadiance = 549755813888.0;

// Checks the channels the file has among these, pixel by pixel (rows top first), each pixel's
// in this order:
//  samples, samplesDiscarded  whole numbers from 0; the two together no more than the file's
//                             sample ranges hold (their counts summed) nor kLargestSampleCount
//  R, G, B                    (an accumulation) finite, from 0 to kLargestMeanRadiance; 0 in a
//                             pixel without a sample kept
//  sumSquaredDeviations.R/G/B finite, from 0 to 2 n (n - 1) mean^2 for the n samples kept: n
//                             non-negative samples of that mean deviate the most from it when
//                             one holds all of it, n (n - 1) mean^2; twice that leaves room for
//                             the rounding of a running mean over 2^24 samples
//  varianceOfMean             (a statistics file) finite, from 0
//  albedo.R/G/B, N.X/Y/Z, Z, coverage  (feature buffers) finite, albedo 0 to 1, normals -1 to
//                             1, depth from 0, coverage 0 to 1.
// Only an OpenEXR file is checked (an 8-bit picture's values are whatever they are). Throws
// std::runtime_error "FILE: pixel (X, Y), channel NAME: VALUE ..." for the first value that
// is not.
void checkPixelValues(const io::ImageFileContents& file, const RenderMetadata& metadata,
                      const std::string& fileName);

// The attribute holding pixelDigest() in the render's EXR.
extern const char* const kPixelDigestAttribute;  // "raytracer:pixelSha256"

// SHA-256, in hex, of every value of `image` as a little-endian 32-bit float, pixel by pixel
// (rows top first), each pixel's channels in the order of their names (as OpenEXR keeps them,
// so that the file read gives the digest of the image written).
std::string pixelDigest(const io::Image& image, const std::vector<std::string>& channelNames);

// Throws std::runtime_error naming `fileName` when the file has kPixelDigestAttribute and its
// pixels are not the ones it was computed from: a byte changed after the file was written
// (where the new value is one a render could hold, checkPixelValues cannot tell). A file
// without it (from before it was written) is not refused for that.
void checkPixelDigest(const io::ImageFileContents& file, const std::string& fileName);

}  // namespace film
