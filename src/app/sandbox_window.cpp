// The GLFW window with Dear ImGui: see sandbox_window.h.
#include "app/sandbox_window.h"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <fmt/core.h>

#include "app/panel_cache.h"
#include "app/platform.h"
#include "app/sandbox_settings.h"
#include "render/changed_regions.h"
#include "render/font.h"
#include "render/glsl_version.h"

namespace polyroll::app {

namespace {

std::string g_glfw_error;  // the last GLFW error, for the one-line "no display" message

void on_glfw_error(int code, const char* text) { g_glfw_error = fmt::format("{} (GLFW error {:#x})", text, code); }

ImVec4 rgb(const std::array<int, 3>& c, float a = 1.0f) {
    return {static_cast<float>(c[0]) / 255.0f, static_cast<float>(c[1]) / 255.0f, static_cast<float>(c[2]) / 255.0f, a};
}
ImVec4 rgb(int r, int g, int b, float a = 1.0f) { return rgb({r, g, b}, a); }

// The projector theme: opaque pale panels, near-black text, strong borders and saturated controls,
// so the panel stays readable when a projector washes out the contrast.
void projector_colours(ImGuiStyle& st) {
    ImGui::StyleColorsLight(&st);
    ImVec4* c = st.Colors;
    c[ImGuiCol_Text] = rgb(kPanelTextRgb);
    c[ImGuiCol_TextDisabled] = rgb(80, 80, 90);
    c[ImGuiCol_WindowBg] = rgb(kPanelBackgroundRgb);
    c[ImGuiCol_ChildBg] = rgb(kPanelBackgroundRgb);
    c[ImGuiCol_PopupBg] = rgb(255, 255, 255);
    c[ImGuiCol_Border] = rgb(40, 44, 52);
    c[ImGuiCol_FrameBg] = rgb(255, 255, 255);
    c[ImGuiCol_FrameBgHovered] = rgb(205, 222, 250);
    c[ImGuiCol_FrameBgActive] = rgb(180, 205, 245);
    c[ImGuiCol_TitleBg] = rgb(200, 210, 228);
    c[ImGuiCol_TitleBgActive] = rgb(200, 210, 228);
    c[ImGuiCol_Button] = rgb(190, 208, 240);
    c[ImGuiCol_ButtonHovered] = rgb(150, 182, 235);
    c[ImGuiCol_ButtonActive] = rgb(110, 150, 225);
    c[ImGuiCol_Header] = rgb(196, 210, 235);
    c[ImGuiCol_HeaderHovered] = rgb(160, 186, 232);
    c[ImGuiCol_HeaderActive] = rgb(130, 165, 225);
    c[ImGuiCol_SliderGrab] = rgb(25, 75, 170);
    c[ImGuiCol_SliderGrabActive] = rgb(10, 50, 140);
    c[ImGuiCol_CheckMark] = rgb(10, 50, 140);
    c[ImGuiCol_Tab] = rgb(196, 210, 235);
    c[ImGuiCol_TabHovered] = rgb(150, 182, 235);
    c[ImGuiCol_TabActive] = rgb(120, 160, 230);
    c[ImGuiCol_Separator] = rgb(90, 95, 105);
    c[ImGuiCol_TableHeaderBg] = rgb(200, 210, 228);
    c[ImGuiCol_TableBorderStrong] = rgb(60, 64, 72);
    c[ImGuiCol_TableBorderLight] = rgb(150, 155, 165);
    c[ImGuiCol_TableRowBgAlt] = rgb(236, 240, 247);
    st.WindowBorderSize = 2.0f;
    st.FrameBorderSize = 1.0f;
}

}  // namespace

std::unique_ptr<Window> Window::open(int width_px, int height_px, bool vsync, std::string& why) {
    glfwSetErrorCallback(on_glfw_error);
    if (!glfwInit()) {
        why = g_glfw_error.empty() ? "GLFW could not start" : g_glfw_error;
        return nullptr;
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    GLFWwindow* w = glfwCreateWindow(width_px, height_px, "polyroll sandbox", nullptr, nullptr);
    if (!w) {
        why = g_glfw_error.empty() ? "no window could be created" : g_glfw_error;
        glfwTerminate();
        return nullptr;
    }
    glfwMakeContextCurrent(w);
    glfwSwapInterval(vsync ? 1 : 0);

    std::unique_ptr<Window> win(new Window());
    win->window_ = w;
    win->font_dir_ = render::find_font_dir();
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // the layout is computed each frame; nothing to remember
    ImGui_ImplGlfw_InitForOpenGL(w, true);
    ImGui_ImplOpenGL3_Init(render::kGlslVersion);
    win->panels_ = std::make_unique<PanelCache>();
    const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    win->present_parts_ = can_present_parts(renderer ? renderer : "");
    // Uncovered or restored, the window lost its pixels; the back buffer still holds them.
    glfwSetWindowUserPointer(w, win.get());
    glfwSetWindowRefreshCallback(w, [](GLFWwindow* gw) {
        static_cast<Window*>(glfwGetWindowUserPointer(gw))->show_all_ = true;
    });
    return win;
}

Window::~Window() {
    panels_.reset();  // its GL objects go while the context is current
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(window_);
    glfwTerminate();
}

bool Window::should_close() const { return glfwWindowShouldClose(window_) != 0; }

void Window::set_ui_scale(float scale) {
    if (scale != scale_) {
        scale_ = scale;
        style_dirty_ = true;
    }
}

void Window::set_high_contrast(bool on) {
    if (on != high_contrast_) {
        high_contrast_ = on;
        style_dirty_ = true;
    }
}

void Window::build_fonts() {
    ImGuiIO& io = ImGui::GetIO();
    // Latin-1, Greek (theta), dashes and the minus sign, arrows and the play/pause shapes.
    static const ImWchar ranges[] = {0x0020, 0x00FF, 0x0370, 0x03FF, 0x2010, 0x2044, 0x2190, 0x21FF,
                                     0x2212, 0x2212, 0x25A0, 0x25FF, 0x2758, 0x275A, 0};
    io.Fonts->Clear();
    const float px = kBaseFontPx * scale_;
    io.Fonts->AddFontFromFileTTF((font_dir_ + "/DejaVuSans.ttf").c_str(), px, nullptr, ranges);
    large_ = io.Fonts->AddFontFromFileTTF((font_dir_ + "/DejaVuSans-Bold.ttf").c_str(), px * 1.3f, nullptr, ranges);
    io.Fonts->Build();
    ImGui_ImplOpenGL3_DestroyFontsTexture();
    ImGui_ImplOpenGL3_CreateFontsTexture();
    if (panels_) panels_->invalidate();  // the copy was drawn with the old atlas
    built_scale_ = scale_;
}

void Window::apply_style() {
    ImGuiStyle st;
    if (high_contrast_) {
        projector_colours(st);
    } else {
        ImGui::StyleColorsDark(&st);
    }
    st.WindowRounding = 0.0f;
    st.FrameRounding = 3.0f;
    st.GrabMinSize = 14.0f;
    st.ScaleAllSizes(scale_);
    ImGui::GetStyle() = st;
    style_dirty_ = false;
}

void Window::begin_frame() {
    glfwPollEvents();
    if (built_scale_ != scale_) build_fonts();
    if (style_dirty_) apply_style();
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
}

void Window::render_ui(render::Rgba panel_background, const render::PxRect& scene,
                       const std::vector<render::ClipRect>* scene_changed) {
    ImGui::Render();
    int w = 0, h = 0;
    framebuffer_size(w, h);
    if (w != kept_w_ || h != kept_h_) kept_ = false;  // a new size is a new back buffer
    changed_ = panels_->render(ImGui::GetDrawData(), panel_background, scene, present_parts_ && kept_);
    const render::ClipRect c = render::covering_pixels(scene);
    if (!scene_changed) {
        changed_.push_back({c.x, c.y, c.x + c.width, c.y + c.height});
        return;
    }
    for (const render::ClipRect& r : *scene_changed) {
        const render::ClipRect in = render::intersection(r, c);
        if (!in.empty()) changed_.push_back({in.x, in.y, in.x + in.width, in.y + in.height});
    }
    // What the panels drew over the scene this frame (an open combo may have appeared there).
    for (const PanelCache::Rect& r : panels_->drawn_in_scene()) changed_.push_back(r);
}

bool Window::holds_last_frame() const {
    int w = 0, h = 0;
    framebuffer_size(w, h);
    return present_parts_ && kept_ && w == kept_w_ && h == kept_h_;
}

std::vector<render::ClipRect> Window::panels_in_scene() const {
    std::vector<render::ClipRect> out;
    for (const PanelCache::Rect& r : panels_->drawn_in_scene()) out.push_back({r.x0, r.y0, r.x1 - r.x0, r.y1 - r.y0});
    return out;
}

void Window::swap() {
    if (!present_parts_) {
        glfwSwapBuffers(window_);
        return;
    }
    int w = 0, h = 0;
    framebuffer_size(w, h);
    if (show_all_ || !kept_) changed_ = {{0, 0, w, h}};
    present_parts(changed_, h);
    kept_ = true;
    show_all_ = false;
    kept_w_ = w;
    kept_h_ = h;
}

void Window::finish_gl() const { glFinish(); }

void Window::wait_events(double timeout_s) const { glfwWaitEventsTimeout(timeout_s); }

void Window::framebuffer_size(int& w, int& h) const { glfwGetFramebufferSize(window_, &w, &h); }

float Window::pixel_ratio() const {
    int fw = 0, fh = 0, ww = 0, wh = 0;
    glfwGetFramebufferSize(window_, &fw, &fh);
    glfwGetWindowSize(window_, &ww, &wh);
    return ww > 0 ? static_cast<float>(fw) / static_cast<float>(ww) : 1.0f;
}

std::vector<std::uint8_t> Window::read_back_buffer(int& w, int& h) const {
    framebuffer_size(w, h);
    std::vector<std::uint8_t> pixels(static_cast<size_t>(w) * static_cast<size_t>(h) * 4);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    return pixels;
}

std::string Window::gl_renderer() const {
    const auto* r = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const auto* v = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    return fmt::format("{} ({})", r ? r : "?", v ? v : "?");
}

}  // namespace polyroll::app
