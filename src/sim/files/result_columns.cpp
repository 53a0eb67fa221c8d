// The columns of a run's tables: see result_columns.h.
#include "sim/files/result_columns.h"

#include <array>

namespace polyroll {

namespace {

using T = TrajectorySample;
using F = FaceImpact;
using Fmt = ColumnFormat;

// The delayed reading only where there is one and an energy before to divide it by.
std::optional<double> delayed_J(const F& f) {
    return f.kinetic_delayed_J && f.kinetic_before_J > 0.0 ? f.kinetic_delayed_J : std::nullopt;
}

constexpr std::array<ResultColumn<T>, 9> kTrajectory = {{
    {"time_s", "s", "time since the release", Fmt::fixed6, [](const T& t) -> std::optional<double> { return t.time_s; }},
    {"position_m", "m", "the lid centre along the ramp from its position at release", Fmt::fixed6,
     [](const T& t) -> std::optional<double> { return t.position_m; }},
    {"speed_m_s", "m/s", "the lid centre's velocity along the ramp (negative when rocking back)", Fmt::fixed6,
     [](const T& t) -> std::optional<double> { return t.speed_m_s; }},
    {"angle_deg", "deg", "the shell's rotation since release, positive rolling down", Fmt::fixed4,
     [](const T& t) -> std::optional<double> { return t.angle_deg; }},
    {"kinetic_J", "J", "kinetic energy of shell and grains", Fmt::general9,
     [](const T& t) -> std::optional<double> { return t.kinetic_J; }},
    {"potential_J", "J", "potential energy of shell and grains, from the release", Fmt::general9,
     [](const T& t) -> std::optional<double> { return t.potential_J; }},
    {"dissipated_J", "J", "energy at release minus kinetic minus potential", Fmt::general9,
     [](const T& t) -> std::optional<double> { return t.dissipated_J; }},
    {"fill_ahead_m", "m", "the fill's centre of mass from the shell's centre, down the ramp (models that move grains)",
     Fmt::fixed6, [](const T& t) { return t.fill_ahead_m; }},
    {"fill_up_m", "m", "the fill's centre of mass from the shell's centre, away from the ramp (models that move grains)",
     Fmt::fixed6, [](const T& t) { return t.fill_up_m; }},
}};

constexpr std::array<ResultColumn<F>, 8> kImpacts = {{
    {"impact", "", "1 for the first face landed", Fmt::integer,
     [](const F& f) -> std::optional<double> { return f.index; }},
    {"time_s", "s", "when the face landed", Fmt::fixed6, [](const F& f) -> std::optional<double> { return f.time_s; }},
    {"position_m", "m", "the lid centre along the ramp then", Fmt::fixed6,
     [](const F& f) -> std::optional<double> { return f.position_m; }},
    {"kinetic_before_J", "J", "kinetic energy just before the landing", Fmt::general9,
     [](const F& f) -> std::optional<double> { return f.kinetic_before_J; }},
    {"kinetic_after_J", "J", "kinetic energy just after it", Fmt::general9,
     [](const F& f) -> std::optional<double> { return f.kinetic_after_J; }},
    {"ratio", "", "after over before", Fmt::fixed6, [](const F& f) -> std::optional<double> { return f.ratio(); }},
    {"kinetic_3ms_after_J", "J", "kinetic energy 3 ms after the landing (models stepped in time)", Fmt::general9,
     delayed_J},
    {"ratio_3ms", "", "that over the energy before", Fmt::fixed6, [](const F& f) -> std::optional<double> {
         const std::optional<double> d = delayed_J(f);
         return d ? std::optional<double>(*d / f.kinetic_before_J) : std::nullopt;
     }},
}};

}  // namespace

std::span<const ResultColumn<TrajectorySample>> trajectory_columns() { return kTrajectory; }
std::span<const ResultColumn<FaceImpact>> impact_columns() { return kImpacts; }

}  // namespace polyroll
