#include "lexel/spatial/harness/image_io.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace lexel::spatial {
namespace {

TEST(ImageIo, PngRoundTripIsExactAtEightBits) {
    Image image = MakeImage(7, 5, 3);
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 7; ++x)
            for (int c = 0; c < 3; ++c)
                image.at(x, y, c) = static_cast<float>((x * 37 + y * 11 + c * 5) % 256) / 255.0f;
    const auto path = std::filesystem::temp_directory_path() / "lexel_image_io_test.png";
    WriteImage(path.string(), image);
    const Image back = ReadImage(path.string());
    ASSERT_EQ(back.width, 7);
    ASSERT_EQ(back.height, 5);
    ASSERT_EQ(back.channels, 3);
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        EXPECT_NEAR(back.pixels[i], image.pixels[i], 1e-6);
    std::filesystem::remove(path);
}

TEST(ImageIo, UnwritablePathThrowsAndLeavesNothing) {
    const Image image = MakeImage(2, 2, 1);
    EXPECT_THROW(WriteImage("/nonexistent-dir/lexel.png", image), std::runtime_error);
    EXPECT_THROW(ReadImage("/nonexistent-dir/lexel.png"), std::runtime_error);
}

}  // namespace
}  // namespace lexel::spatial
