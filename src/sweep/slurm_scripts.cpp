// The Slurm batch scripts of a sweep folder: see slurm_scripts.h.
#include "sweep/slurm_scripts.h"

#include <fmt/core.h>

namespace polyroll::sweep {

namespace fs = std::filesystem;

namespace {

bool safe_shell_char(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '/' || c == '.' ||
           c == '_' || c == '-' || c == '+' || c == ',' || c == ':' || c == '=' || c == '@' || c == '%';
}

// A value of an #SBATCH line: sbatch reads these itself (no shell), and takes a value with spaces
// between double quotes.
std::string sbatch_value(const std::string& text) {
    return text.find_first_of(" \t") == std::string::npos ? text : "\"" + text + "\"";
}

std::string command_line(const std::vector<std::string>& argv) {
    std::string out;
    for (const std::string& a : argv) out += (out.empty() ? "" : " ") + shell_quoted(a);
    return out;
}

}  // namespace

std::string shell_quoted(const std::string& text) {
    bool safe = !text.empty();
    for (char c : text) safe = safe && safe_shell_char(c);
    if (safe) return text;
    std::string out = "'";
    for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

std::string slurm_job_name(const std::string& command, const fs::path& dir) {
    std::string folder;
    for (char c : dir.filename().string())
        if ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' || c == '_' ||
            c == '-')
            folder += c;
    return folder.empty() ? "polyroll-" + command : "polyroll-" + command + "-" + folder;
}

fs::path slurm_array_script_path(const fs::path& dir) { return dir / "slurm" / "array.sbatch"; }
fs::path slurm_finish_script_path(const fs::path& dir) { return dir / "slurm" / "merge.sbatch"; }

std::string slurm_array_script(const SlurmJob& job) {
    const fs::path logs = job.dir / "slurm";
    std::string s = "#!/bin/sh\n";
    s += fmt::format("# Task K of this job array runs slice K of {} of the plan in {} (polyroll's --shard K/{}),\n"
                     "# with --cpus-per-task runs at a time. Written by polyroll; edit freely (e.g. add #SBATCH\n"
                     "# --time or --partition), then: sbatch {}\n"
                     "# A task that did not finish (cancelled, pre-empted, timed out) is run again with\n"
                     "#   sbatch --array=K {}\n"
                     "# and resumes: it skips the runs its table already holds. Then run {}.\n",
                     job.tasks, job.dir.string(), job.tasks, slurm_array_script_path(job.dir).string(),
                     slurm_array_script_path(job.dir).string(), slurm_finish_script_path(job.dir).string());
    s += fmt::format("#SBATCH --job-name={}\n", sbatch_value(job.name));
    s += fmt::format("#SBATCH --array=1-{}\n", job.tasks);
    s += fmt::format("#SBATCH --cpus-per-task={}\n", job.cpus_per_task);
    s += fmt::format("#SBATCH --output={}\n", sbatch_value((logs / "array-%A_%a.out").string()));
    s += fmt::format("#SBATCH --chdir={}\n", sbatch_value(job.dir.string()));
    s += fmt::format("exec {} --shard \"${{SLURM_ARRAY_TASK_ID}}/{}\" --jobs \"${{SLURM_CPUS_PER_TASK:-1}}\" --quiet\n",
                     command_line(job.task_argv), job.tasks);
    return s;
}

std::string slurm_finish_script(const SlurmJob& job) {
    const fs::path logs = job.dir / "slurm";
    std::string s = "#!/bin/sh\n";
    if (job.finish_what == "merge")
        s += fmt::format("# Combines the tables of the {} slices in {} into its results.csv. Submitted to run after\n"
                         "# every task of {} (--dependency=afterany:<array job id>); exits 1 naming\n"
                         "# the plan indices no table holds if a task did not finish: run that task again, then this.\n",
                         job.tasks, job.dir.string(), slurm_array_script_path(job.dir).string());
    else
        s += fmt::format("# The last step after the {} slices in {} ({}): the same command without --shard finds\n"
                         "# every slice done, runs whatever is left, merges the tables and writes the results. Submitted\n"
                         "# to run after every task of {} (--dependency=afterany:<array job id>).\n",
                         job.tasks, job.dir.string(), job.finish_what, slurm_array_script_path(job.dir).string());
    s += fmt::format("#SBATCH --job-name={}\n", sbatch_value(job.name + "-" + job.finish_what));
    s += "#SBATCH --cpus-per-task=1\n";
    s += fmt::format("#SBATCH --output={}\n", sbatch_value((logs / (job.finish_what + "-%j.out")).string()));
    s += fmt::format("#SBATCH --chdir={}\n", sbatch_value(job.dir.string()));
    s += fmt::format("exec {}\n", command_line(job.finish_argv));
    return s;
}

}  // namespace polyroll::sweep
