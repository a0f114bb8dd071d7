#include "lexel/spatial/harness/image_io.h"

#include <OpenImageIO/imageio.h>

#include <filesystem>
#include <stdexcept>

namespace lexel::spatial {

Image MakeImage(int width, int height, int channels, float fill) {
    Image image{width, height, channels, {}};
    image.pixels.assign(static_cast<std::size_t>(width) * height * channels, fill);
    return image;
}

void WriteImage(const std::string& path, const Image& image) {
    const std::filesystem::path target(path);
    // Keep the extension last so OpenImageIO picks the format from it.
    const std::filesystem::path temporary =
        target.parent_path() / (target.stem().string() + ".partial" + target.extension().string());
    auto out = OIIO::ImageOutput::create(temporary.string());
    if (!out) throw std::runtime_error(path + ": " + OIIO::geterror());
    const bool isFloat = target.extension() == ".exr";
    OIIO::ImageSpec spec(image.width, image.height, image.channels,
                         isFloat ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
    if (!out->open(temporary.string(), spec) ||
        !out->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data()) || !out->close()) {
        const std::string message = out->geterror();
        std::filesystem::remove(temporary);
        throw std::runtime_error(path + ": " + message);
    }
    std::filesystem::rename(temporary, target);
}

Image ReadImage(const std::string& path) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) throw std::runtime_error(path + ": " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    Image image = MakeImage(spec.width, spec.height, spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data()))
        throw std::runtime_error(path + ": " + in->geterror());
    in->close();
    return image;
}

}  // namespace lexel::spatial
