// Image files for the 3D harness (frames, misclassification maps, shadow maps): OpenImageIO,
// linked through pkg-config (Debian's CMake config for it is broken).
#pragma once

#include <string>
#include <vector>

namespace lexel::spatial {

// Interleaved float pixels, row-major from the top row, values in [0, 1] for 8-bit outputs.
struct Image {
    int width = 0, height = 0, channels = 0;
    std::vector<float> pixels;
    float& at(int x, int y, int c) {
        return pixels[(static_cast<std::size_t>(y) * width + x) * channels + c];
    }
    float at(int x, int y, int c) const {
        return pixels[(static_cast<std::size_t>(y) * width + x) * channels + c];
    }
};

Image MakeImage(int width, int height, int channels, float fill = 0.0f);

// The format follows the extension (.png writes 8 bits per channel, .exr floats). Throws
// std::runtime_error with OpenImageIO's message on failure. Written through a temporary file and
// a rename, so a failed write leaves nothing behind. OpenImageIO's PNG writer does not report
// every short write (a full disk left a truncated PNG and no error): files that must be complete
// are checked after writing (cases::OutputSet does so for every --out image).
void WriteImage(const std::string& path, const Image& image);
Image ReadImage(const std::string& path);

}  // namespace lexel::spatial
