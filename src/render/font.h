// Text for the overlay: DejaVu Sans (Debian's fonts-dejavu-core) rasterised once with FreeType into
// a coverage atlas at the few pixel sizes a frame uses, then laid out as whole-pixel glyph quads.
// GL-free: the atlas is an image the GL renderer uploads, and text widths are known to the layout.
// The same FreeType and font give the same pixels, so frames stay byte-identical run to run.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "render/draw_list.h"

namespace polyroll::render {

enum class FontFace : std::uint8_t { regular, bold };

struct FontSpec {
    FontFace face = FontFace::regular;
    int size_px = 16;  // FreeType pixel size (about the height of a capital plus descent)
    auto operator<=>(const FontSpec&) const = default;
};

// Where the fonts are looked for; the first folder holding both files wins. Throws
// std::runtime_error saying which package to install when none does.
std::string find_font_dir();

class FontAtlas {
public:
    // Rasterises printable ASCII and the few symbols the overlay uses (degree, theta, minus, times,
    // middle dot, superscript two) at each spec.
    FontAtlas(const std::string& font_dir, const std::vector<FontSpec>& specs);

    // Unique per atlas made in this process: tells a renderer when to upload again.
    std::uint64_t id() const { return id_; }
    int width() const { return width_; }
    int height() const { return height_; }
    const std::vector<std::uint8_t>& coverage() const { return pixels_; }  // width x height, top row first

    float text_width(std::string_view utf8, FontSpec spec) const;
    float ascent(FontSpec spec) const;   // baseline below the top of a line
    float line_height(FontSpec spec) const;

    // Appends the glyphs of `utf8` with the pen starting at `baseline_left`; returns the advance.
    float layout(std::string_view utf8, FontSpec spec, Px baseline_left, Rgba colour,
                 std::vector<GlyphQuad>& out) const;

private:
    struct Glyph {
        int x = 0, y = 0, w = 0, h = 0;  // in the atlas
        int left = 0, top = 0;           // bitmap offset from the pen (top is up from the baseline)
        float advance = 0.0f;
    };
    struct Sized {
        std::map<char32_t, Glyph> glyphs;
        float ascent = 0.0f, line_height = 0.0f;
    };
    const Glyph* glyph(const Sized& s, char32_t c) const;
    const Sized& sized(FontSpec spec) const;

    std::uint64_t id_ = 0;
    int width_ = 0, height_ = 0;
    std::vector<std::uint8_t> pixels_;
    std::map<FontSpec, Sized> sizes_;
};

// Decodes UTF-8 (invalid bytes become '?').
std::u32string decode_utf8(std::string_view s);

}  // namespace polyroll::render
