// The 3D reference as a ModelRun (--model dem3d): the scene's box and every grain of its fill
// simulated in Yade by polyroll_dem3d.py (a subprocess, yade_process.h), measured from the states it
// records by the tracker's rules (state_tracker.h), and revealed in the tracker's steps like the
// models computed whole at once, so `run`, `sweep`, `render` and the comparisons take it unchanged.
// It costs about a minute of CPU for a whole-ramp run: a reference for checks, never for the window.
#pragma once

#include <filesystem>
#include <vector>

#include "sim/dem3d/state_tracker.h"
#include "sim/model_run.h"

namespace polyroll::dem3d {

// One frame of the grains' positions, for drawing.
struct GrainFrame {
    double time_s = 0.0;
    std::vector<GrainState> grains;
};

// Reads grains.csv (time_s,grain,x_m,y_m,z_m,radius_m) into frames; `depth_m` is the box's inside
// length, for each grain's depth share.
std::vector<GrainFrame> parse_grains_csv(const std::string& text, double depth_m);

// What the script wrote in `dir` (states.csv, setup.json, grains.csv if any), read and measured as
// a run of `scene`: the result and the states and frames to show it by. Throws std::runtime_error
// naming the file and line of what cannot be read.
struct Dem3dOutput {
    RunResult result;
    std::vector<StateRow> rows;
    std::vector<GrainFrame> frames;
};
Dem3dOutput read_output(const Scene& scene, const std::filesystem::path& dir);

class Dem3dRun final : public ModelRun {
public:
    // Runs Yade to the end (a minute or so), then shows the run step by step; throws InputError if
    // Yade is missing and std::runtime_error if it fails.
    explicit Dem3dRun(const Scene& scene);

    bool step() override;
    bool finished() const override;
    long steps() const override { return steps_; }
    const Scene& scene() const override { return scene_; }
    RunSnapshot snapshot() const override;
    const Measurements& measured() const override { return shown_; }
    RunResult result() const override { return full_; }
    int grains() const override { return full_.grains; }
    HandOver hand_over() const override;
    void run_to_end() override;
    std::unique_ptr<ModelRun> replay() const override;

private:
    Dem3dRun(const Dem3dRun&) = default;
    StateRow state_now() const;  // at time_s(), held at the end
    void reveal();

    Scene scene_;
    RunResult full_;
    std::vector<StateRow> rows_;
    std::vector<GrainFrame> frames_;
    std::vector<geom::Vec2> outer_, inner_;
    Measurements shown_;
    long steps_ = 0;
};

}  // namespace polyroll::dem3d
