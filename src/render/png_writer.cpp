// PNG encoding and decoding with libpng: see png_writer.h.
#include "render/png_writer.h"

#include <cstring>
#include <stdexcept>

#include <png.h>

#include <fmt/core.h>

#include "sim/files/atomic_file.h"

namespace polyroll::render {

namespace {

void append_bytes(png_structp png, png_bytep data, png_size_t length) {
    auto* out = static_cast<std::vector<std::uint8_t>*>(png_get_io_ptr(png));
    out->insert(out->end(), data, data + length);
}
void no_flush(png_structp) {}

// libpng reports errors by longjmp to png_jmpbuf; this function holds no C++ objects that a jump
// past it would skip destroying.
bool encode_rows(png_structp png, png_infop info, std::vector<std::uint8_t>* out, const ImageView& im) {
    if (setjmp(png_jmpbuf(png))) return false;
    const int width = im.width, height = im.height;
    png_set_write_fn(png, out, append_bytes, no_flush);
    png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8, PNG_COLOR_TYPE_RGB,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_compression_level(png, 1);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
    png_write_info(png, info);
    // libpng drops the fourth byte itself, and rows go in either order: the GL buffer needs no
    // conversion on the rendering thread.
    if (im.channels == 4) png_set_filler(png, 0, PNG_FILLER_AFTER);
    const size_t stride = static_cast<size_t>(width) * static_cast<size_t>(im.channels);
    for (int y = 0; y < height; ++y) {
        const size_t row = static_cast<size_t>(im.bottom_up ? height - 1 - y : y);
        png_write_row(png, const_cast<png_bytep>(im.pixels + row * stride));
    }
    png_write_end(png, info);
    return true;
}

}  // namespace

std::vector<std::uint8_t> encode_png(const ImageView& image) {
    if (image.channels != 3 && image.channels != 4) throw std::logic_error("encode_png: 3 or 4 channels");
    const int width = image.width, height = image.height;
    std::vector<std::uint8_t> out;
    out.reserve(static_cast<size_t>(width) * static_cast<size_t>(height) / 4);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    if (!png) throw std::runtime_error("libpng: cannot create a write struct");
    png_infop info = png_create_info_struct(png);
    const bool ok = info && encode_rows(png, info, &out, image);
    png_destroy_write_struct(&png, &info);
    if (!ok) throw std::runtime_error(fmt::format("libpng: cannot encode a {}x{} frame", width, height));
    return out;
}

void write_file_whole(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes) {
    // Unsynced: a frame is cheap to make again, and syncing hundreds of files would dominate.
    write_file_atomic(path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()),
                      Durability::unsynced);
}

DecodedPng read_png(const std::filesystem::path& path) {
    png_image image;
    std::memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&image, path.c_str()))
        throw std::runtime_error(fmt::format("{}: not a readable PNG ({})", path.string(), image.message));
    image.format = PNG_FORMAT_RGB;
    DecodedPng d;
    d.width = static_cast<int>(image.width);
    d.height = static_cast<int>(image.height);
    d.rgb.resize(PNG_IMAGE_SIZE(image));
    if (!png_image_finish_read(&image, nullptr, d.rgb.data(), 0, nullptr)) {
        const std::string msg = image.message;
        png_image_free(&image);
        throw std::runtime_error(fmt::format("{}: cannot decode ({})", path.string(), msg));
    }
    return d;
}

}  // namespace polyroll::render
