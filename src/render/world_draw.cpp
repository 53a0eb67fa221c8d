// The ramp, the shell and the grains as draw-list items: see world_draw.h.
#include "render/world_draw.h"

#include <algorithm>
#include <cmath>

#include <fmt/core.h>

#include "render/ticks.h"

namespace polyroll::render {

using geom::Vec2;

std::vector<Vec2> shell_world_polygon(const Snapshot& s, bool outer) {
    const std::vector<Vec2>& local = outer ? s.outer_local_m : s.inner_local_m;
    std::vector<Vec2> out;
    out.reserve(local.size());
    for (const Vec2& v : local)
        out.push_back(ramp_to_world(s.shell_centre_m + geom::rotate(v, s.shell_angle_rad), s.ramp_angle_deg));
    return out;
}

double outer_radius_m(const Snapshot& s) {
    double r = 0.0;
    for (const Vec2& v : s.outer_local_m) r = std::max(r, geom::length(v));
    return r;
}

Rgba grain_colour(const Snapshot& s, const GrainState& g, GrainColouring how, double speed_max_m_s) {
    if (how == GrainColouring::speed) return speed_colour(g.speed_m_s / std::max(speed_max_m_s, 1e-9));
    return material_colour(s.material);
}

namespace {

// The colour darkened towards black: `light` 1 keeps it, 0 is black.
Rgba shade(Rgba c, float light) { return {c.r * light, c.g * light, c.b * light, c.a}; }

bool inside(Px p, const PxRect& r, float pad) {
    return p.x >= r.x - pad && p.x <= r.x + r.width + pad && p.y >= r.y - pad && p.y <= r.y + r.height + pad;
}

void draw_ramp(const Snapshot& s, const Camera& cam, const WorldStyle& st, const FontAtlas& font, Layer& out) {
    const double deg = s.ramp_angle_deg;
    const double L = s.ramp_length_m;
    const double band_m = kRampBodyDesignPx * st.unit / cam.px_per_m;  // the body's thickness stays readable at any zoom
    auto P = [&](double x, double y) { return cam.to_px(ramp_to_world({x, y}, deg)); };
    const Px a = P(0, 0), b = P(L, 0), c = P(L, -band_m), d = P(0, -band_m);
    out.triangles.push_back({a, b, c, palette::ramp_body, Tag::ramp_body});
    out.triangles.push_back({a, c, d, palette::ramp_body, Tag::ramp_body});
    // Strokes over the body's edges antialias them.
    const float edge = std::max(1.0f, 1.5f * st.unit);
    out.shapes.push_back(segment(d, c, edge, palette::ramp_body, Tag::ramp_body));
    out.shapes.push_back(segment(a, d, edge, palette::ramp_body, Tag::ramp_body));
    out.shapes.push_back(segment(b, c, edge, palette::ramp_body, Tag::ramp_body));

    // Length scale: minor ticks at least 9 design pixels apart, labelled majors at least 110.
    const double minor = nice_ceil(9.0 * st.unit / cam.px_per_m);
    double major = nice_ceil(110.0 * st.unit / cam.px_per_m);
    major = std::max(major, 2.0 * minor);
    const long per_major = std::max(1L, std::lround(major / minor));
    const long count = static_cast<long>(std::floor(L / minor + 1e-9));
    const float tick_w = std::max(1.0f, 1.5f * st.unit);
    for (long i = 0; i <= count; ++i) {
        const double x = static_cast<double>(i) * minor;
        const Px top = P(x, 0);
        if (!inside(top, st.visible, 200.0f * st.unit)) continue;
        const bool is_major = i % per_major == 0;
        const Px end = P(x, -band_m * (is_major ? 0.95 : 0.5));
        out.shapes.push_back(segment(P(x, -band_m * 0.05), end, is_major ? 1.5f * tick_w : tick_w,
                                     palette::ramp_tick, Tag::ramp_tick));
        if (!is_major) continue;
        // Metres at every zoom, so the close-up and the view never label the same ramp in two units.
        const std::string label = fmt::format("{:g} m", std::round(x * 1000.0) / 1000.0);
        const float tw = font.text_width(label, st.scale_font);
        const Px under = P(x, -band_m - 6.0 * st.unit / cam.px_per_m);
        // A label that would be cut at the picture's edge (the close-up's bottom, the view's side)
        // is left out: a whole label or none, never "0." or "1.5" of "1.5 m".
        const PxRect box{under.x - tw / 2.0f, under.y, tw, font.line_height(st.scale_font)};
        if (box.x < st.visible.x || box.y < st.visible.y || box.x + box.width > st.visible.x + st.visible.width ||
            box.y + box.height > st.visible.y + st.visible.height)
            continue;
        font.layout(label, st.scale_font, {under.x - tw / 2.0f, under.y + font.ascent(st.scale_font)},
                    palette::scale_text, out.glyphs);
    }
    // The surface the shell rolls on, drawn last so it is crisp.
    out.shapes.push_back(segment(a, b, std::max(1.5f, 3.0f * st.unit), palette::ramp_surface, Tag::ramp_surface));
}

void draw_shell_and_grains(const Snapshot& s, const Camera& cam, const WorldStyle& st, Layer& out) {
    std::vector<Px> outer, inner;
    for (const Vec2& v : shell_world_polygon(s, true)) outer.push_back(cam.to_px(v));
    for (const Vec2& v : shell_world_polygon(s, false)) inner.push_back(cam.to_px(v));
    const size_t n = outer.size();
    if (n < 3 || inner.size() != n) return;
    for (size_t i = 1; i + 1 < n; ++i)
        out.triangles.push_back({inner[0], inner[i], inner[i + 1], palette::shell_inside, Tag::shell_inside});
    // A fill the model holds as one body, in the grains' colour, turning with the shell (a convex
    // region: a fan from its first corner covers it).
    std::vector<Px> fill;
    for (const Vec2& v : s.fill_region_local_m)
        fill.push_back(cam.to_px(ramp_to_world(s.shell_centre_m + geom::rotate(v, s.shell_angle_rad), s.ramp_angle_deg)));
    for (size_t i = 1; i + 1 < fill.size(); ++i)
        out.triangles.push_back({fill[0], fill[i], fill[i + 1], material_colour(s.material), Tag::fill_region});
    // Outlined in the grains' colour darkened, so a pale fill (rice) held as one body still shows its
    // edge where it is not the shell's wall (the rigid model's frozen fill, the segments' levelled one).
    for (size_t i = 0; fill.size() >= 3 && i < fill.size(); ++i)
        out.shapes.push_back(segment(fill[i], fill[(i + 1) % fill.size()], 0.8f * st.stroke,
                                     shade(material_colour(s.material), 0.55f), Tag::fill_region));
    for (size_t i = 0; i < n; ++i) {
        const size_t j = (i + 1) % n;
        out.triangles.push_back({inner[i], outer[i], outer[j], st.shell_wall, Tag::shell_wall});
        out.triangles.push_back({inner[i], outer[j], inner[j], st.shell_wall, Tag::shell_wall});
    }
    for (size_t i = 0; i < n; ++i) {
        const size_t j = (i + 1) % n;
        out.shapes.push_back(segment(outer[i], outer[j], st.stroke, palette::shell_outline, Tag::shell_outline));
        out.shapes.push_back(segment(inner[i], inner[j], 0.6f * st.stroke, palette::shell_outline, Tag::shell_outline));
    }
    // 3D grains (--model dem3d) projected on the cross-section: the farthest drawn first, so the
    // nearer cover them, and each darkened with its distance from the viewer so the pile reads as deep.
    std::vector<const GrainState*> order;
    order.reserve(s.grains.size());
    for (const GrainState& g : s.grains) order.push_back(&g);
    // 2D grains have no depth (all -1): their order is the list's, with no sort a frame.
    if (std::any_of(s.grains.begin(), s.grains.end(), [](const GrainState& g) { return g.depth >= 0.0; }))
        std::stable_sort(order.begin(), order.end(),
                         [](const GrainState* a, const GrainState* b) { return a->depth > b->depth; });
    // The material's colour looked up once, not for each of a big pile's grains.
    const Rgba material = material_colour(s.material);
    for (const GrainState* g : order) {
        const Px c = cam.to_px(ramp_to_world(g->position_m, s.ramp_angle_deg));
        const float r = cam.to_px_length(g->radius_m);
        // Small grains get a thin outline so neighbours stay apart without turning into dark dots.
        const float outline = std::min(1.2f * st.unit, 0.2f * r);
        Rgba fill = st.grain_colouring == GrainColouring::speed
                        ? grain_colour(s, *g, st.grain_colouring, st.colour_speed_max_m_s)
                        : material;
        if (g->depth >= 0.0) fill = shade(fill, static_cast<float>(1.0 - 0.55 * g->depth));
        out.shapes.push_back(disc(c, r, fill, Tag::grain, outline, palette::grain_outline));
    }
    // The tracked dot at the lid's centre, on top: the lid is in front of the grains.
    double inner_r_m = 0.0;
    for (const Vec2& v : s.inner_local_m) inner_r_m = std::max(inner_r_m, geom::length(v));
    const Px centre = cam.to_px(ramp_to_world(s.shell_centre_m, s.ramp_angle_deg));
    const float dot_r = std::max(2.5f * st.unit, 0.08f * cam.to_px_length(inner_r_m));
    out.shapes.push_back(disc(centre, dot_r + std::max(1.0f, 1.5f * st.unit), palette::lid_dot_ring, Tag::lid_dot));
    out.shapes.push_back(disc(centre, dot_r, palette::lid_dot, Tag::lid_dot));
}

}  // namespace

namespace {
// A fill the model holds as one body says so where it is drawn large enough to read (the close-up):
// a full shell of rice is otherwise a pale block that reads as an empty shell.
void label_fill_region(const Snapshot& s, const Camera& cam, const WorldStyle& st, const FontAtlas& font, Layer& out) {
    if (s.fill_region_local_m.size() < 3) return;
    float x0 = 1e30f, x1 = -1e30f, y0 = 1e30f, y1 = -1e30f;
    for (const Vec2& v : s.fill_region_local_m) {
        const Px p = cam.to_px(ramp_to_world(s.shell_centre_m + geom::rotate(v, s.shell_angle_rad), s.ramp_angle_deg));
        x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    }
    const std::string text = "rigid body";
    const float width = font.text_width(text, st.scale_font), height = font.line_height(st.scale_font);
    // Inside the region's box with room to spare, below the lid's dot at its centre.
    if (width > 0.85f * (x1 - x0) || 3.0f * height > (y1 - y0)) return;
    const float cx = 0.5f * (x0 + x1), cy = 0.5f * (y0 + y1) + 1.2f * height;
    font.layout(text, st.scale_font, {cx - width / 2.0f, cy - height / 2.0f + font.ascent(st.scale_font)},
                shade(material_colour(s.material), 0.35f), out.glyphs);
}
}  // namespace

void draw_world(const Snapshot& s, const Camera& cam, const WorldStyle& style, const FontAtlas& font, Layer& out) {
    draw_ramp(s, cam, style, font, out);
    draw_shell_and_grains(s, cam, style, out);
    label_fill_region(s, cam, style, font, out);
}

}  // namespace polyroll::render
