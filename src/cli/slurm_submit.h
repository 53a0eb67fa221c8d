// --slurm-tasks N and its companions (polyroll sweep --plan-only, polyroll validate): a sweep folder's
// plan as a Slurm job array. Writes DIR/slurm/array.sbatch and DIR/slurm/merge.sbatch
// (sweep/slurm_scripts.h) and, where sbatch is on PATH, submits the array and then the finishing job
// with --dependency=afterany:<array job id>; without sbatch (or with --slurm-no-submit) it prints the
// two sbatch commands to run.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "flags/command_flags.h"

#include "sweep/slurm_scripts.h"

namespace polyroll::cli {

struct SlurmFlags {
    int tasks = 0;  // --slurm-tasks N; 0: not given
    int cpus_per_task = 1;
    bool no_submit = false;
    flags::Flag cpus_option;
    flags::Flag no_submit_option;

    bool asked() const { return tasks > 0; }
};

// Registers --slurm-tasks, --slurm-cpus-per-task and --slurm-no-submit on `sub` (group "Slurm").
// `needs` says in the help what --slurm-tasks goes with (sweep: "with --out DIR --plan-only").
void add_slurm_flags(flags::Command& sub, const std::shared_ptr<SlurmFlags>& flags, const std::string& needs);

// Refuses (InputError) --slurm-cpus-per-task or --slurm-no-submit without --slurm-tasks, and an array
// of more tasks than the plan has runs (a task with nothing to do).
void check_slurm_flags(const SlurmFlags& flags);
void check_slurm_tasks_for_plan(const SlurmFlags& flags, std::size_t runs);

// This program's absolute path (/proc/self/exe), for the scripts to run the same binary.
std::string this_program();

// Writes the job's two scripts and, unless `flags.no_submit` or sbatch is not on PATH, submits them.
// `who` starts each line ("polyroll sweep"). Returns the exit code: 0, or 1 when sbatch failed (the
// scripts are written then, and the line says how to submit them by hand).
int write_and_submit_slurm(const sweep::SlurmJob& job, const SlurmFlags& flags, const std::string& who);

}  // namespace polyroll::cli
