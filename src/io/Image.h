#pragma once
#include <cstddef>
#include <vector>

namespace io {

// A float image in memory, rows top first (as pictures are written), channels interleaved.
struct Image {
    int width = 0;
    int height = 0;
    int channels = 0;
    std::vector<float> pixels;

    Image() = default;
    Image(int width, int height, int channels);

    float& at(int x, int y, int channel);
    float at(int x, int y, int channel) const;
    std::size_t index(int x, int y, int channel) const;
};

}  // namespace io
