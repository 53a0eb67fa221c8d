// The text of the two Slurm batch scripts that run a sweep folder's plan on a cluster: a job array
// whose task K of N runs slice K of the plan (`--shard K/N`), and the job that finishes it (the merge
// of the slices' tables, or validate's scoring). Text only: cli/slurm_submit writes and submits them.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace polyroll::sweep {

// Bounds of the flags that ask for a job array (--slurm-tasks, --slurm-cpus-per-task).
inline constexpr int kMaxSlurmTasks = 10000;
inline constexpr int kMaxSlurmCpusPerTask = 1024;

struct SlurmJob {
    std::string name;                 // the job name, e.g. "polyroll-sweep-big" (the merge job adds "-merge")
    std::filesystem::path dir;        // the sweep folder, absolute; the scripts and their logs go to dir/slurm/
    int tasks = 1;                    // N: the array runs tasks 1..N, task K the slice K/N
    int cpus_per_task = 1;            // each task's --jobs
    // What each task runs, before " --shard ${SLURM_ARRAY_TASK_ID}/N --jobs ${SLURM_CPUS_PER_TASK:-1}
    // --quiet": the binary's absolute path first, e.g. {"/opt/bin/polyroll", "sweep", "--from", "/s/big"}.
    std::vector<std::string> task_argv;
    // What the finishing job runs, e.g. {"/opt/bin/polyroll", "sweep", "--merge", "/s/big"}.
    std::vector<std::string> finish_argv;
    std::string finish_what = "merge";  // what the finishing job does, for its comment and job name
};

// `text` as one word of a POSIX shell: unchanged when it holds only safe characters, else in single
// quotes (a ' inside written as '\'').
std::string shell_quoted(const std::string& text);

// A job name Slurm shows in squeue: "polyroll-<command>-<folder's name>", the folder's name cut to
// letters, digits, '.', '_' and '-'.
std::string slurm_job_name(const std::string& command, const std::filesystem::path& dir);

// dir/slurm/array.sbatch and dir/slurm/merge.sbatch.
std::filesystem::path slurm_array_script_path(const std::filesystem::path& dir);
std::filesystem::path slurm_finish_script_path(const std::filesystem::path& dir);

// The job array's script: #SBATCH --job-name, --array=1-N, --cpus-per-task, --output into dir/slurm/
// (array-<array job id>_<task>.out), --chdir; then the task's command.
std::string slurm_array_script(const SlurmJob& job);

// The finishing job's script (one task, its output in dir/slurm/<finish_what>-<job id>.out).
std::string slurm_finish_script(const SlurmJob& job);

}  // namespace polyroll::sweep
