// The columns of a run's tables, declared once: trajectory.csv and impacts.csv are written from these
// rows, and Python's Result.trajectory and Result.impacts are built from them, so a column added here
// appears in both with the same name, unit and value. A blank (an empty CSV cell, NaN in Python) is a
// value the model does not have.
#pragma once

#include <optional>
#include <span>
#include <string_view>

#include "sim/measurements.h"

namespace polyroll {

// How a column's numbers are written in the CSV (Python gets the double itself).
enum class ColumnFormat {
    fixed6,    // {:.6f}: times, positions, speeds, ratios
    fixed4,    // {:.4f}: angles in degrees
    general9,  // {:.9g}: energies, whose sizes span decades
    integer,   // a count
};

template <class Row>
struct ResultColumn {
    std::string_view name;     // the CSV header and the Python field
    std::string_view unit;     // "" for a pure number
    std::string_view meaning;
    ColumnFormat format;
    std::optional<double> (*value)(const Row&);  // empty: a blank
};

// trajectory.csv, one row per sample.
std::span<const ResultColumn<TrajectorySample>> trajectory_columns();
// impacts.csv, one row per face landed.
std::span<const ResultColumn<FaceImpact>> impact_columns();

}  // namespace polyroll
