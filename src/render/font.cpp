// FreeType glyph atlas and text layout: see font.h.
#include "render/font.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include <ft2build.h>
#include FT_FREETYPE_H

#include <fmt/core.h>

namespace polyroll::render {

namespace {

constexpr const char* kRegularFile = "DejaVuSans.ttf";
constexpr const char* kBoldFile = "DejaVuSans-Bold.ttf";
constexpr int kAtlasWidth = 1024;
constexpr int kPadding = 1;  // empty texels between glyphs

std::u32string charset() {
    std::u32string s;
    for (char32_t c = 32; c < 127; ++c) s.push_back(c);
    s += U"\u00B0\u03B8\u2212\u00D7\u00B7\u00B2\u2013";
    return s;
}

struct FtLibrary {
    FT_Library lib = nullptr;
    FtLibrary() {
        if (FT_Init_FreeType(&lib) != 0) throw std::runtime_error("cannot initialise FreeType");
    }
    ~FtLibrary() { FT_Done_FreeType(lib); }
};

struct FtFace {
    FT_Face face = nullptr;
    FtFace(FT_Library lib, const std::string& path) {
        if (FT_New_Face(lib, path.c_str(), 0, &face) != 0)
            throw std::runtime_error(fmt::format("cannot read the font {}", path));
    }
    ~FtFace() { FT_Done_Face(face); }
};

}  // namespace

std::string find_font_dir() {
    const char* env = std::getenv("POLYROLL_FONT_DIR");
    std::vector<std::string> dirs;
    if (env && *env) dirs.emplace_back(env);
    dirs.emplace_back("/usr/share/fonts/truetype/dejavu");
    for (const std::string& d : dirs) {
        std::error_code ec;
        if (std::filesystem::exists(std::filesystem::path(d) / kRegularFile, ec) &&
            std::filesystem::exists(std::filesystem::path(d) / kBoldFile, ec))
            return d;
    }
    throw std::runtime_error(fmt::format("the overlay font ({} and {}) is not in /usr/share/fonts/truetype/dejavu: "
                                         "install it with 'apt-get install fonts-dejavu-core' "
                                         "(or set POLYROLL_FONT_DIR to a folder holding them)",
                                         kRegularFile, kBoldFile));
}

std::u32string decode_utf8(std::string_view s) {
    std::u32string out;
    for (size_t i = 0; i < s.size();) {
        const auto b = static_cast<unsigned char>(s[i]);
        int extra = 0;
        char32_t c = 0;
        if (b < 0x80) c = b;
        else if ((b & 0xE0) == 0xC0) { c = b & 0x1F; extra = 1; }
        else if ((b & 0xF0) == 0xE0) { c = b & 0x0F; extra = 2; }
        else if ((b & 0xF8) == 0xF0) { c = b & 0x07; extra = 3; }
        else { out.push_back(U'?'); ++i; continue; }
        if (i + static_cast<size_t>(extra) >= s.size()) {  // truncated sequence
            out.push_back(U'?');
            break;
        }
        bool ok = true;
        for (int k = 1; k <= extra; ++k) {
            const auto cb = static_cast<unsigned char>(s[i + static_cast<size_t>(k)]);
            if ((cb & 0xC0) != 0x80) ok = false;
            c = (c << 6) | (cb & 0x3F);
        }
        out.push_back(ok ? c : U'?');
        i += static_cast<size_t>(ok ? extra + 1 : 1);
    }
    return out;
}

FontAtlas::FontAtlas(const std::string& font_dir, const std::vector<FontSpec>& specs) {
    static std::atomic<std::uint64_t> next_id{1};
    id_ = next_id++;
    FtLibrary ft;
    FtFace regular(ft.lib, (std::filesystem::path(font_dir) / kRegularFile).string());
    FtFace bold(ft.lib, (std::filesystem::path(font_dir) / kBoldFile).string());

    struct Bitmap {
        FontSpec spec;
        char32_t code;
        Glyph g;
        std::vector<std::uint8_t> pixels;
    };
    std::vector<Bitmap> bitmaps;
    const std::u32string chars = charset();
    for (const FontSpec& spec : specs) {
        if (sizes_.count(spec)) continue;
        FT_Face face = spec.face == FontFace::bold ? bold.face : regular.face;
        FT_Set_Pixel_Sizes(face, 0, static_cast<FT_UInt>(std::max(spec.size_px, 4)));
        Sized& sz = sizes_[spec];
        sz.ascent = static_cast<float>(face->size->metrics.ascender) / 64.0f;
        sz.line_height = static_cast<float>(face->size->metrics.height) / 64.0f;
        for (char32_t c : chars) {
            if (FT_Load_Char(face, c, FT_LOAD_RENDER | FT_LOAD_TARGET_NORMAL) != 0) continue;
            const FT_GlyphSlot slot = face->glyph;
            Bitmap bm;
            bm.spec = spec;
            bm.code = c;
            bm.g.w = static_cast<int>(slot->bitmap.width);
            bm.g.h = static_cast<int>(slot->bitmap.rows);
            bm.g.left = slot->bitmap_left;
            bm.g.top = slot->bitmap_top;
            // Whole-pixel advances keep glyphs on the pixel grid, so they are never resampled.
            bm.g.advance = std::round(static_cast<float>(slot->advance.x) / 64.0f);
            bm.pixels.resize(static_cast<size_t>(bm.g.w) * static_cast<size_t>(bm.g.h));
            for (int row = 0; row < bm.g.h; ++row)
                for (int col = 0; col < bm.g.w; ++col)
                    bm.pixels[static_cast<size_t>(row) * static_cast<size_t>(bm.g.w) + static_cast<size_t>(col)] =
                        slot->bitmap.buffer[row * slot->bitmap.pitch + col];
            bitmaps.push_back(std::move(bm));
        }
    }
    // Shelf packing, tallest first so rows waste little.
    std::vector<size_t> order(bitmaps.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return bitmaps[a].g.h > bitmaps[b].g.h; });
    int x = kPadding, y = kPadding, row_h = 0;
    for (size_t i : order) {
        Glyph& g = bitmaps[i].g;
        if (x + g.w + kPadding > kAtlasWidth) {
            x = kPadding;
            y += row_h + kPadding;
            row_h = 0;
        }
        g.x = x;
        g.y = y;
        x += g.w + kPadding;
        row_h = std::max(row_h, g.h);
    }
    width_ = kAtlasWidth;
    height_ = 1;
    while (height_ < y + row_h + kPadding) height_ *= 2;
    pixels_.assign(static_cast<size_t>(width_) * static_cast<size_t>(height_), 0);
    for (const Bitmap& bm : bitmaps) {
        for (int row = 0; row < bm.g.h; ++row)
            std::copy_n(bm.pixels.begin() + static_cast<std::ptrdiff_t>(row) * bm.g.w, bm.g.w,
                        pixels_.begin() + static_cast<std::ptrdiff_t>(bm.g.y + row) * width_ + bm.g.x);
        sizes_[bm.spec].glyphs[bm.code] = bm.g;
    }
}

const FontAtlas::Sized& FontAtlas::sized(FontSpec spec) const {
    auto it = sizes_.find(spec);
    if (it == sizes_.end())
        throw std::logic_error(fmt::format("font size {} px was not rasterised into the atlas", spec.size_px));
    return it->second;
}

const FontAtlas::Glyph* FontAtlas::glyph(const Sized& s, char32_t c) const {
    auto it = s.glyphs.find(c);
    if (it != s.glyphs.end()) return &it->second;
    it = s.glyphs.find(U'?');
    return it != s.glyphs.end() ? &it->second : nullptr;
}

float FontAtlas::text_width(std::string_view utf8, FontSpec spec) const {
    const Sized& s = sized(spec);
    float w = 0.0f;
    for (char32_t c : decode_utf8(utf8))
        if (const Glyph* g = glyph(s, c)) w += g->advance;
    return w;
}

float FontAtlas::ascent(FontSpec spec) const { return sized(spec).ascent; }
float FontAtlas::line_height(FontSpec spec) const { return sized(spec).line_height; }

float FontAtlas::layout(std::string_view utf8, FontSpec spec, Px baseline_left, Rgba colour,
                        std::vector<GlyphQuad>& out) const {
    const Sized& s = sized(spec);
    const float x0 = std::round(baseline_left.x), base = std::round(baseline_left.y);
    float pen = x0;
    const float iw = 1.0f / static_cast<float>(width_), ih = 1.0f / static_cast<float>(height_);
    for (char32_t c : decode_utf8(utf8)) {
        const Glyph* g = glyph(s, c);
        if (!g) continue;
        if (g->w > 0 && g->h > 0) {
            GlyphQuad q;
            q.p0 = {pen + static_cast<float>(g->left), base - static_cast<float>(g->top)};
            q.p1 = {q.p0.x + static_cast<float>(g->w), q.p0.y + static_cast<float>(g->h)};
            q.u0 = static_cast<float>(g->x) * iw;
            q.v0 = static_cast<float>(g->y) * ih;
            q.u1 = static_cast<float>(g->x + g->w) * iw;
            q.v1 = static_cast<float>(g->y + g->h) * ih;
            q.colour = colour;
            out.push_back(q);
        }
        pen += g->advance;
    }
    return pen - x0;
}

}  // namespace polyroll::render
