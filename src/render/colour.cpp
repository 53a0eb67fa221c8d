// Material colours and the speed colour map: see colour.h.
#include "render/colour.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace polyroll::render {

Rgba material_colour(const std::string& preset) {
    // Close to the real things, and distinct from the blue shell and the light inside.
    if (preset == "bb") return rgb8(236, 170, 30);    // yellow-orange plastic BBs
    if (preset == "peas") return rgb8(96, 160, 50);   // green peas
    if (preset == "rice") return rgb8(250, 246, 228); // white rice (dark outline keeps it visible)
    return rgb8(170, 120, 200);
}

Rgba speed_colour(double t) {
    // Control points picked by eye for even lightness steps; linear in between.
    static constexpr std::array<Rgba, 5> stops = {rgb8(68, 1, 84), rgb8(59, 82, 139), rgb8(33, 145, 140),
                                                  rgb8(94, 201, 98), rgb8(253, 231, 37)};
    if (!(t > 0.0)) return stops.front();  // also catches NaN
    if (t >= 1.0) return stops.back();
    const double x = t * static_cast<double>(stops.size() - 1);
    const size_t i = static_cast<size_t>(std::floor(x));
    const float f = static_cast<float>(x - static_cast<double>(i));
    const Rgba& a = stops[i];
    const Rgba& b = stops[std::min(i + 1, stops.size() - 1)];
    return {a.r + (b.r - a.r) * f, a.g + (b.g - a.g) * f, a.b + (b.b - a.b) * f, 1.0f};
}

}  // namespace polyroll::render
