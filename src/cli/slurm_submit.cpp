// A sweep folder's plan as a Slurm job array: see slurm_submit.h.
#include "cli/slurm_submit.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <string_view>

#include <fmt/core.h>

#include "cli/commands.h"
#include "process/child_process.h"
#include "sim/files/atomic_file.h"
#include "sim/errors.h"
#include "sim/message_text.h"

namespace polyroll::cli {

namespace fs = std::filesystem;

void add_slurm_flags(flags::Command& sub, const std::shared_ptr<SlurmFlags>& flags, const std::string& needs) {
    sub.add_option("--slurm-tasks", flags->tasks,
                   fmt::format("{}: write slurm/array.sbatch in the folder, a Slurm job array of N tasks (1 to {}; "
                               "task K runs --shard K/N), and slurm/merge.sbatch, the step after it; submit both "
                               "when sbatch is on PATH",
                               needs, sweep::kMaxSlurmTasks))
        .check(flags::Range(1, sweep::kMaxSlurmTasks))
        .group("Slurm");
    flags->cpus_option = sub.add_option("--slurm-cpus-per-task", flags->cpus_per_task,
                                        fmt::format("with --slurm-tasks: CPUs each task asks for and runs at a time "
                                                    "(its --jobs), 1 to {} (default 1)",
                                                    sweep::kMaxSlurmCpusPerTask))
                             .check(flags::Range(1, sweep::kMaxSlurmCpusPerTask))
                             .group("Slurm");
    flags->no_submit_option =
        sub.add_flag("--slurm-no-submit", flags->no_submit,
                     "with --slurm-tasks: write the scripts and print the sbatch commands, submit nothing")
            .group("Slurm");
}

void check_slurm_flags(const SlurmFlags& flags) {
    if (flags.asked()) return;
    if (flags.cpus_option.count() > 0)
        throw InputError(fmt::format("--slurm-cpus-per-task {} needs --slurm-tasks N (allowed: --slurm-tasks 1 to {})",
                                     flags.cpus_per_task, sweep::kMaxSlurmTasks));
    if (flags.no_submit_option.count() > 0)
        throw InputError(fmt::format("--slurm-no-submit needs --slurm-tasks N (allowed: --slurm-tasks 1 to {})",
                                     sweep::kMaxSlurmTasks));
}

void check_slurm_tasks_for_plan(const SlurmFlags& flags, std::size_t runs) {
    if (flags.asked() && static_cast<std::size_t>(flags.tasks) > runs)
        throw InputError(fmt::format("--slurm-tasks {} is more tasks than the plan has runs (allowed: 1 to {}; a task "
                                     "with no run would do nothing)",
                                     flags.tasks, runs));
}

std::string this_program() {
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (ec) throw std::runtime_error("cannot read /proc/self/exe (this program's path): " + ec.message());
    return self.string();
}

namespace {

// What sbatch said, as it said it: one indented line per line (each made printable on its own), so
// a multi-line error reads as lines and never runs into the message's next sentence.
std::string indented_lines(std::string_view said) {
    std::string out;
    for (std::size_t start = 0; start <= said.size();) {
        const std::size_t end = std::min(said.find('\n', start), said.size());
        out += "\n    " + printable_line(said.substr(start, end - start));
        start = end + 1;
    }
    return out;
}

// `sbatch --parsable ARGS...`: the job id it printed ("123" or "123;cluster"), or "" with `why` set
// (how sbatch ended, then what it said on lines of their own).
std::string submit(const std::string& sbatch, const std::vector<std::string>& args, std::string& why) {
    std::vector<std::string> argv = {sbatch, "--parsable"};
    argv.insert(argv.end(), args.begin(), args.end());
    std::string id;
    process::ChildOptions o;
    o.keep_stderr = true;
    o.time_limit_s = 120.0;
    o.on_output_line = [&id](const std::string& line) {
        if (id.empty()) id = line.substr(0, line.find(';'));
    };
    const process::ChildExit e = process::run_child(argv, o);
    const bool numeric = !id.empty() && std::all_of(id.begin(), id.end(), [](unsigned char c) { return std::isdigit(c); });
    std::string said = e.stderr_tail;
    while (!said.empty() && (said.back() == '\n' || said.back() == ' ')) said.pop_back();
    if (e.succeeded() && numeric) {
        if (!said.empty()) fmt::print(stderr, "{}\n", said);  // sbatch's warnings, if any
        return id;
    }
    why = fmt::format("sbatch ({}){}", e.how_it_ended(),
                      said.empty() ? (numeric ? "" : ", no job id printed") : " said:" + indented_lines(said));
    return {};
}

}  // namespace

int write_and_submit_slurm(const sweep::SlurmJob& job, const SlurmFlags& flags, const std::string& who) {
    const fs::path array = sweep::slurm_array_script_path(job.dir), finish = sweep::slurm_finish_script_path(job.dir);
    fs::create_directories(array.parent_path());
    write_file_atomic(array, sweep::slurm_array_script(job));
    write_file_atomic(finish, sweep::slurm_finish_script(job));
    for (const fs::path& p : {array, finish})
        fs::permissions(p, fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec,
                        fs::perm_options::add);
    fmt::print("{}: Slurm job array of {} written: {} (then {})\n", who, counted(job.tasks, "task"), array.string(),
               finish.string());
    const std::string array_q = sweep::shell_quoted(array.string()), finish_q = sweep::shell_quoted(finish.string());
    const std::string by_hand = fmt::format("    jobid=$(sbatch --parsable {})\n"
                                            "    sbatch --dependency=afterany:$jobid {}\n",
                                            array_q, finish_q);
    const std::string sbatch = flags.no_submit ? std::string() : process::find_on_path("sbatch");
    if (sbatch.empty()) {
        fmt::print("  {}; submit them with:\n{}", flags.no_submit ? "not submitted (--slurm-no-submit)"
                                                                   : "not submitted: sbatch is not on PATH",
                   by_hand);
        return kExitOk;
    }
    std::fflush(stdout);
    std::string why;
    const std::string array_id = submit(sbatch, {array.string()}, why);
    if (array_id.empty()) {
        fmt::print(stderr, "{}: the job array was not submitted: {}\n  the scripts are written; submit them with:\n{}",
                   who, why, by_hand);
        return kExitFailure;
    }
    const std::string finish_id = submit(sbatch, {"--dependency=afterany:" + array_id, finish.string()}, why);
    if (finish_id.empty()) {
        fmt::print(stderr, "{}: job array {} submitted, but not the {} job: {}\n  submit it with:\n"
                   "    sbatch --dependency=afterany:{} {}\n",
                   who, array_id, job.finish_what, why, array_id, finish_q);
        return kExitFailure;
    }
    fmt::print("{}: submitted job array {} ({}) and {} job {} (runs when every task has ended)\n", who, array_id,
               counted(job.tasks, "task"), job.finish_what, finish_id);
    fmt::print("  watch:         squeue -j {},{}   (task K's output: {})\n", array_id, finish_id,
               (job.dir / "slurm" / fmt::format("array-{}_K.out", array_id)).string());
    fmt::print("  rerun task K:  sbatch --array=K {}   (it resumes: the runs its table holds are skipped)\n", array_q);
    fmt::print("  {:<14} sbatch {}\n", fmt::format("then {}:", job.finish_what), finish_q);
    return kExitOk;
}

}  // namespace polyroll::cli
