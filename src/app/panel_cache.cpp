// Panels from a copy: see panel_cache.h.
#define GL_GLEXT_PROTOTYPES 1
#include "app/panel_cache.h"

#include <GL/gl.h>
#include <GL/glext.h>
#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cmath>
#include <cstring>


namespace polyroll::app {

namespace {

using Rect = PanelCache::Rect;

Rect unite(const Rect& a, const Rect& b) {
    if (a.empty()) return b;
    if (b.empty()) return a;
    return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

Rect intersect(const Rect& a, const Rect& b) {
    return {std::max(a.x0, b.x0), std::max(a.y0, b.y0), std::min(a.x1, b.x1), std::min(a.y1, b.y1)};
}

bool same(const Rect& a, const Rect& b) { return a.x0 == b.x0 && a.y0 == b.y0 && a.x1 == b.x1 && a.y1 == b.y1; }

// 64-bit FNV-1a, eight bytes at a step: a frame's lists are 100-200 kB, hashed in well under a millisecond.
struct Hash {
    std::uint64_t h = 14695981039346656037ull;
    void add(const void* data, std::size_t n) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (; n >= 8; n -= 8, p += 8) {
            std::uint64_t w = 0;
            std::memcpy(&w, p, 8);
            h = (h ^ w) * 1099511628211ull;
        }
        for (; n > 0; --n, ++p) h = (h ^ *p) * 1099511628211ull;
    }
    template <class T>
    void add(const T& value) {
        add(&value, sizeof value);
    }
};

std::uint64_t list_hash(const ImDrawList& l) {
    Hash h;
    h.add(l.VtxBuffer.Data, static_cast<std::size_t>(l.VtxBuffer.Size) * sizeof(ImDrawVert));
    h.add(l.IdxBuffer.Data, static_cast<std::size_t>(l.IdxBuffer.Size) * sizeof(ImDrawIdx));
    for (const ImDrawCmd& c : l.CmdBuffer) {
        h.add(c.ClipRect);
        h.add(c.TextureId);
        h.add(c.VtxOffset);
        h.add(c.IdxOffset);
        h.add(c.ElemCount);
        h.add(c.UserCallback);
    }
    return h.h;
}

// ImGui coordinates to framebuffer pixels, rows from the top, as the backend's scissor maps them.
struct ToPixels {
    ImVec2 offset, scale;
    float x(float v) const { return (v - offset.x) * scale.x; }
    float y(float v) const { return (v - offset.y) * scale.y; }
};

// What a list can touch: its vertices' box within its commands' clip rectangles, a pixel wider for
// the rasteriser's rounding, inside the framebuffer.
Rect list_bounds(const ImDrawList& l, const ToPixels& px, const Rect& frame) {
    if (l.VtxBuffer.Size == 0 || l.CmdBuffer.Size == 0) return {};
    float x0 = l.VtxBuffer[0].pos.x, y0 = l.VtxBuffer[0].pos.y, x1 = x0, y1 = y0;
    for (const ImDrawVert& v : l.VtxBuffer) {
        x0 = std::min(x0, v.pos.x);
        y0 = std::min(y0, v.pos.y);
        x1 = std::max(x1, v.pos.x);
        y1 = std::max(y1, v.pos.y);
    }
    ImVec4 clip = l.CmdBuffer[0].ClipRect;
    for (const ImDrawCmd& c : l.CmdBuffer) {
        clip.x = std::min(clip.x, c.ClipRect.x);
        clip.y = std::min(clip.y, c.ClipRect.y);
        clip.z = std::max(clip.z, c.ClipRect.z);
        clip.w = std::max(clip.w, c.ClipRect.w);
    }
    const Rect r{static_cast<int>(std::floor(px.x(std::max(x0, clip.x)))) - 1,
                 static_cast<int>(std::floor(px.y(std::max(y0, clip.y)))) - 1,
                 static_cast<int>(std::ceil(px.x(std::min(x1, clip.z)))) + 1,
                 static_cast<int>(std::ceil(px.y(std::min(y1, clip.w)))) + 1};
    return intersect(r, frame);
}

}  // namespace

PanelCache::PanelCache() {
    glGenTextures(1, &texture_);
    glGenFramebuffers(1, &framebuffer_);
}

PanelCache::~PanelCache() {
    glDeleteFramebuffers(1, &framebuffer_);
    glDeleteTextures(1, &texture_);
}

void PanelCache::resize(int width_px, int height_px) {
    width_px_ = width_px;
    height_px_ = height_px;
    glBindTexture(GL_TEXTURE_2D, texture_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width_px, height_px, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    lists_.clear();
}

std::vector<Rect> PanelCache::render(ImDrawData* data, render::Rgba background, const render::PxRect& scene,
                                     bool kept) {
    const int w = static_cast<int>(data->DisplaySize.x * data->FramebufferScale.x);
    const int h = static_cast<int>(data->DisplaySize.y * data->FramebufferScale.y);
    if (w <= 0 || h <= 0) return {};  // minimised
    if (w != width_px_ || h != height_px_) resize(w, h);
    if (background.r != background_.r || background.g != background_.g || background.b != background_.b) {
        background_ = background;
        lists_.clear();
    }

    const ToPixels px{data->DisplayPos, data->FramebufferScale};
    const Rect frame{0, 0, w, h};
    std::vector<ListState> now(static_cast<std::size_t>(data->CmdListsCount));
    for (std::size_t i = 0; i < now.size(); ++i) {
        const ImDrawList& l = *data->CmdLists[i];
        now[i] = {&l, list_hash(l), list_bounds(l, px, frame)};
    }
    // A list changed, appeared or went: where it is now and where it was are drawn again.
    Rect dirty = lists_.empty() ? frame : Rect{};
    for (std::size_t i = 0; i < std::max(now.size(), lists_.size()); ++i) {
        const bool is_now = i < now.size(), was = i < lists_.size();
        if (is_now && was && now[i].list == lists_[i].list && now[i].hash == lists_[i].hash &&
            same(now[i].bounds, lists_[i].bounds))
            continue;
        if (is_now) dirty = unite(dirty, now[i].bounds);
        if (was) dirty = unite(dirty, lists_[i].bounds);
    }
    if (!dirty.empty()) {
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
        glEnable(GL_SCISSOR_TEST);
        glScissor(dirty.x0, h - dirty.y1, dirty.x1 - dirty.x0, dirty.y1 - dirty.y0);
        glClearColor(background.r, background.g, background.b, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        draw_clipped(data, now, dirty);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }

    // The scene's pixels (render::covering_pixels, as the scene's own drawing clips them): the copy
    // goes everywhere else, the lists' own pixels inside it are drawn over the scene.
    const render::ClipRect c = render::covering_pixels(scene);
    const Rect inside = intersect({c.x, c.y, c.x + c.width, c.y + c.height}, frame);
    // A framebuffer that kept the last frame outside the scene needs only what changed there, unless
    // the scene moved (the strips around it are others). On a first frame or a new size `dirty` is the
    // whole frame (no lists yet).
    const Rect copied = kept && same(inside, inside_) ? dirty : frame;
    inside_ = inside;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glDisable(GL_SCISSOR_TEST);
    const Rect strips[4] = {{0, 0, w, inside.y0},
                            {0, inside.y1, w, h},
                            {0, inside.y0, inside.x0, inside.y1},
                            {inside.x1, inside.y0, w, inside.y1}};
    std::vector<Rect> drawn;
    for (const Rect& strip : inside.empty() ? std::vector<Rect>{frame} : std::vector<Rect>(strips, strips + 4)) {
        const Rect s = intersect(strip, copied);
        if (s.empty()) continue;
        // GL counts rows from the bottom.
        glBlitFramebuffer(s.x0, h - s.y1, s.x1, h - s.y0, s.x0, h - s.y1, s.x1, h - s.y0, GL_COLOR_BUFFER_BIT,
                          GL_NEAREST);
        drawn.push_back(s);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    drawn_in_scene_.clear();
    if (!inside.empty()) {
        draw_clipped(data, now, inside);
        for (const ListState& l : now)
            if (const Rect r = intersect(l.bounds, inside); !r.empty()) drawn_in_scene_.push_back(r);
    }
    lists_ = std::move(now);
    return drawn;
}

void PanelCache::draw_clipped(ImDrawData* data, const std::vector<ListState>& now, const Rect& clip) const {
    // The backend sets its own scissor per command and skips a command whose clip rectangle is empty:
    // each command's rectangle is cut to `clip` and put back after.
    const ImVec4 clip_im{clip.x0 / data->FramebufferScale.x + data->DisplayPos.x,
                         clip.y0 / data->FramebufferScale.y + data->DisplayPos.y,
                         clip.x1 / data->FramebufferScale.x + data->DisplayPos.x,
                         clip.y1 / data->FramebufferScale.y + data->DisplayPos.y};
    std::vector<ImDrawList*> lists;
    std::vector<ImVec4> kept;
    ImDrawData part = *data;
    part.TotalVtxCount = part.TotalIdxCount = 0;
    for (std::size_t i = 0; i < now.size(); ++i) {
        if (intersect(now[i].bounds, clip).empty()) continue;
        ImDrawList* l = data->CmdLists[i];
        lists.push_back(l);
        part.TotalVtxCount += l->VtxBuffer.Size;
        part.TotalIdxCount += l->IdxBuffer.Size;
        for (ImDrawCmd& c : l->CmdBuffer) {
            kept.push_back(c.ClipRect);
            c.ClipRect = {std::max(c.ClipRect.x, clip_im.x), std::max(c.ClipRect.y, clip_im.y),
                          std::min(c.ClipRect.z, clip_im.z), std::min(c.ClipRect.w, clip_im.w)};
        }
    }
    if (lists.empty()) return;
    part.CmdLists = lists.data();
    part.CmdListsCount = static_cast<int>(lists.size());
    ImGui_ImplOpenGL3_RenderDrawData(&part);
    std::size_t k = 0;
    for (ImDrawList* l : lists)
        for (ImDrawCmd& c : l->CmdBuffer) c.ClipRect = kept[k++];
}

}  // namespace polyroll::app
