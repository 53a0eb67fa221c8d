// Material colours and the speed colour map: see colour.h.
#include "render/colour.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "sim/assets.h"

namespace polyroll::render {

Rgba material_colour(const std::string& preset) {
    const std::array<int, 3> rgb = assets::material_look(preset).rgb;
    return rgb8(rgb[0], rgb[1], rgb[2]);
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
