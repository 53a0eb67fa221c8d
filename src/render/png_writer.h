// PNG encoding with libpng, tuned for speed: compression level 1 and no row filters (about three
// times faster than libpng's defaults at 1280x720 for a few percent more bytes), RGB, 8 bits.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace polyroll::render {

// Pixels to encode: `channels` bytes per pixel (3 RGB, or 4 RGBA whose alpha is dropped), rows
// top first, or bottom first as a GL framebuffer holds them.
struct ImageView {
    const std::uint8_t* pixels = nullptr;
    int width = 0, height = 0;
    int channels = 3;
    bool bottom_up = false;
};

// Always writes RGB, 8 bits. Throws std::runtime_error.
std::vector<std::uint8_t> encode_png(const ImageView& image);

// Writes under a temporary name and renames, so a frame on disk is never half written.
void write_file_whole(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes);

// Decodes an 8-bit RGB or RGBA PNG to RGB (for tests and checks). Throws std::runtime_error.
struct DecodedPng {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgb;
};
DecodedPng read_png(const std::filesystem::path& path);

}  // namespace polyroll::render
