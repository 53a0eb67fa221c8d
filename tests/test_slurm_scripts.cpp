// --slurm-tasks N (polyroll sweep --plan-only, polyroll validate): the text of the job array's and the
// merge job's scripts, their submission through sbatch (a stand-in sbatch that records its arguments),
// the two sbatch commands printed where there is no sbatch, and bad input refused with one line, exit 2,
// nothing written. The real cluster is tests/slurm_cluster_test.sh's.
#include <catch2/catch.hpp>

#include "test_helpers.h"

#include <filesystem>
#include <fstream>

#include "sweep/slurm_scripts.h"

namespace fs = std::filesystem;

namespace {

using polyroll::test::kPolyrollExe;
using polyroll::test::read_file;
using polyroll::test::run_command;

const polyroll::test::Scratch slurm_scratch("slurm-");

// Four cheap runs.
const std::string kSlurmGrid = "--sides 6,8 --fill 0 --angle 10,20 --fidelity draft --time-limit 0.2";

// A folder holding a stand-in `sbatch` that appends its arguments to calls.txt and prints a job id
// as sbatch --parsable does (41 for the first call, 42 for the second; "41;cluster" the form with a cluster).
fs::path fake_sbatch(const fs::path& dir) {
    fs::create_directories(dir);
    const fs::path sbatch = dir / "sbatch";
    std::ofstream(sbatch) << "#!/bin/sh\n"
                             "echo \"$*\" >> '"
                          << (dir / "calls.txt").string()
                          << "'\n"
                             "if [ \"$(wc -l < '"
                          << (dir / "calls.txt").string()
                          << "')\" -eq 1 ]; then echo '41;cluster'; else echo 42; fi\n";
    fs::permissions(sbatch, fs::perms::owner_all);
    return sbatch;
}

}  // namespace

TEST_CASE("slurm scripts: the job array runs slice K of N, the merge job merges, paths quoted", "[slurm][sweep]") {
    using namespace polyroll::sweep;
    SlurmJob job{slurm_job_name("sweep", "/data/my sweeps/big"), "/data/my sweeps/big", 16, 8,
                 {"/opt/polyroll/bin/polyroll", "sweep", "--from", "/data/my sweeps/big"},
                 {"/opt/polyroll/bin/polyroll", "sweep", "--merge", "/data/my sweeps/big"}};
    CHECK(job.name == "polyroll-sweep-big");
    const std::string array = slurm_array_script(job);
    CHECK(array.rfind("#!/bin/sh\n", 0) == 0);
    for (const char* line : {"--job-name=polyroll-sweep-big", "--array=1-16", "--cpus-per-task=8",
                             "--output=\"/data/my sweeps/big/slurm/array-%A_%a.out\"", "--chdir=\"/data/my sweeps/big\""})
        CHECK_THAT(array, Catch::Contains(std::string("\n#SBATCH ") + line + "\n"));
    CHECK_THAT(array, Catch::EndsWith("\nexec /opt/polyroll/bin/polyroll sweep --from '/data/my sweeps/big' --shard "
                                      "\"${SLURM_ARRAY_TASK_ID}/16\" --jobs \"${SLURM_CPUS_PER_TASK:-1}\" --quiet\n"));
    // How to run a task again, in the script itself.
    CHECK_THAT(array, Catch::Contains("sbatch --array=K /data/my sweeps/big/slurm/array.sbatch"));
    const std::string merge = slurm_finish_script(job);
    CHECK_THAT(merge, Catch::Contains("\n#SBATCH --job-name=polyroll-sweep-big-merge\n"));
    CHECK_THAT(merge, Catch::Contains("\n#SBATCH --output=\"/data/my sweeps/big/slurm/merge-%j.out\"\n"));
    CHECK_THAT(merge, Catch::Contains("\n#SBATCH --cpus-per-task=1\n"));
    CHECK_THAT(merge, Catch::EndsWith("\nexec /opt/polyroll/bin/polyroll sweep --merge '/data/my sweeps/big'\n"));
    CHECK_THAT(merge, !Catch::Contains("--array"));
    CHECK(slurm_array_script_path("/s/big") == fs::path("/s/big/slurm/array.sbatch"));
    CHECK(slurm_finish_script_path("/s/big") == fs::path("/s/big/slurm/merge.sbatch"));

    CHECK(shell_quoted("/plain/path_1.json") == "/plain/path_1.json");
    CHECK(shell_quoted("it's") == "'it'\\''s'");
    CHECK(shell_quoted("$HOME") == "'$HOME'");
    CHECK(shell_quoted("") == "''");
    CHECK(slurm_job_name("validate", "/x/$weird name!") == "polyroll-validate-weirdname");
    CHECK(slurm_job_name("sweep", "/") == "polyroll-sweep");
}

TEST_CASE("slurm: sweep --plan-only --slurm-tasks submits the array, then the merge after it", "[slurm][sweep][cli]") {
    const fs::path out = slurm_scratch("submit"), bin = slurm_scratch("submit-bin");
    fake_sbatch(bin);
    const auto r = run_command("PATH=" + bin.string() + ":$PATH " + kPolyrollExe + " sweep " + kSlurmGrid + " --out " +
                               out.string() + " --plan-only --slurm-tasks 3 --slurm-cpus-per-task 2");
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    const fs::path array = out / "slurm" / "array.sbatch", merge = out / "slurm" / "merge.sbatch";
    CHECK(read_file(bin / "calls.txt") ==
          "--parsable " + array.string() + "\n--parsable --dependency=afterany:41 " + merge.string() + "\n");
    CHECK_THAT(r.out, Catch::Contains("submitted job array 41 (3 tasks) and merge job 42"));
    CHECK_THAT(r.out, Catch::Contains("squeue -j 41,42"));
    CHECK_THAT(r.out, Catch::Contains("sbatch --array=K " + array.string()));
    CHECK(fs::exists(out / "plan.json"));
    CHECK_FALSE(fs::exists(out / "results.csv"));
    // The running binary and the folder, by absolute paths.
    const std::string self = fs::canonical(kPolyrollExe).string();
    CHECK_THAT(read_file(array), Catch::Contains("\n#SBATCH --array=1-3\n") &&
                                     Catch::Contains("\n#SBATCH --cpus-per-task=2\n") &&
                                     Catch::Contains("\nexec " + self + " sweep --from " + out.string() +
                                                     " --shard \"${SLURM_ARRAY_TASK_ID}/3\""));
    CHECK_THAT(read_file(merge), Catch::Contains("\nexec " + self + " sweep --merge " + out.string() + "\n"));
    fs::remove_all(out);
    fs::remove_all(bin);
}

TEST_CASE("slurm: sbatch's failure is printed as its own lines, then how to submit by hand", "[slurm][sweep][cli]") {
    const fs::path out = slurm_scratch("refused"), bin = slurm_scratch("refused-bin");
    fs::create_directories(bin);
    // sbatch as a cluster refuses a job: two lines on stderr, exit 1.
    std::ofstream(bin / "sbatch") << "#!/bin/sh\n"
                                     "echo 'sbatch: error: Batch job submission failed: Invalid account' >&2\n"
                                     "echo 'sbatch: error: see sacctmgr' >&2\n"
                                     "exit 1\n";
    fs::permissions(bin / "sbatch", fs::perms::owner_all);
    const auto r = run_command("PATH=" + bin.string() + ":$PATH " + kPolyrollExe + " sweep " + kSlurmGrid + " --out " +
                               out.string() + " --plan-only --slurm-tasks 2");
    INFO(r.out);
    CHECK(r.exit_code != 0);
    CHECK_THAT(r.out, Catch::Contains("the job array was not submitted: sbatch (exit 1) said:\n"
                                      "    sbatch: error: Batch job submission failed: Invalid account\n"
                                      "    sbatch: error: see sacctmgr\n"
                                      "  the scripts are written; submit them with:\n"
                                      "    jobid=$(sbatch --parsable "));
    CHECK_THAT(r.out, !Catch::Contains("\\x0A"));
    fs::remove_all(out);
    fs::remove_all(bin);
}

TEST_CASE("slurm: without sbatch, or with --slurm-no-submit, the two sbatch commands are printed", "[slurm][sweep][cli]") {
    const fs::path out = slurm_scratch("nosbatch"), bin = slurm_scratch("nosbatch-bin");
    const auto r = run_command("PATH=/nonexistent " + kPolyrollExe + " sweep " + kSlurmGrid + " --out " + out.string() +
                               " --plan-only --slurm-tasks 4");
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.out, Catch::Contains("not submitted: sbatch is not on PATH"));
    CHECK_THAT(r.out, Catch::Contains("jobid=$(sbatch --parsable " + (out / "slurm" / "array.sbatch").string() + ")"));
    CHECK_THAT(r.out, Catch::Contains("sbatch --dependency=afterany:$jobid " + (out / "slurm" / "merge.sbatch").string()));
    CHECK_THAT(read_file(out / "slurm" / "array.sbatch"), Catch::Contains("\n#SBATCH --array=1-4\n"));

    // --slurm-no-submit with an sbatch on PATH: written, not submitted.
    fake_sbatch(bin);
    fs::remove_all(out);
    const auto kept = run_command("PATH=" + bin.string() + ":$PATH " + kPolyrollExe + " sweep " + kSlurmGrid + " --out " +
                                  out.string() + " --plan-only --slurm-tasks 2 --slurm-no-submit");
    INFO(kept.out);
    REQUIRE(kept.exit_code == 0);
    CHECK_THAT(kept.out, Catch::Contains("not submitted (--slurm-no-submit)"));
    CHECK_FALSE(fs::exists(bin / "calls.txt"));
    CHECK(fs::exists(out / "slurm" / "merge.sbatch"));
    fs::remove_all(out);
    fs::remove_all(bin);
}

TEST_CASE("slurm: validate --slurm-tasks writes the plan, its tasks run --shard K/N, the last step scores",
          "[slurm][validate][cli]") {
    const fs::path out = slurm_scratch("validate");
    const auto r = run_command("POLYROLL_PYTHON=/bin/false " + kPolyrollExe +
                               " validate --only fig7-hexagon-rolls --seeds 2 --fidelity draft --set ramp.friction=0.5 "
                               "--out " + out.string() + " --slurm-tasks 2 --slurm-no-submit");
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    CHECK(fs::exists(out / "plan.json"));
    CHECK_FALSE(fs::exists(out / "results.csv"));
    CHECK_FALSE(fs::exists(out / "scorecard.csv"));
    const std::string self = fs::canonical(kPolyrollExe).string();
    const std::string cmd = self + " validate --only fig7-hexagon-rolls --seeds 2 --fidelity draft --set "
                                   "ramp.friction=0.5 --out " + out.string();
    CHECK_THAT(read_file(out / "slurm" / "array.sbatch"),
               Catch::Contains("\nexec " + cmd + " --shard \"${SLURM_ARRAY_TASK_ID}/2\"") &&
                   Catch::Contains("#SBATCH --job-name=polyroll-validate-"));
    CHECK_THAT(read_file(out / "slurm" / "merge.sbatch"),
               Catch::Contains("\nexec " + cmd + " --jobs 1 --quiet\n") && Catch::Contains("-score\n"));
    fs::remove_all(out);
}

TEST_CASE("slurm: bad --slurm flags give one line naming the value and what is allowed, exit 2, nothing written",
          "[slurm][cli][bad-input]") {
    const fs::path out = slurm_scratch("bad");
    struct Case {
        std::string args;
        std::vector<std::string> words;
    };
    const std::string sweep = " sweep " + kSlurmGrid + " --out " + out.string();
    const std::vector<Case> cases = {
        {sweep + " --plan-only --slurm-tasks 0", {"--slurm-tasks 0 is out of range (allowed: 1 to 10000)"}},
        {sweep + " --plan-only --slurm-tasks 10001", {"--slurm-tasks 10001 is out of range (allowed: 1 to 10000)"}},
        {sweep + " --plan-only --slurm-tasks four", {"--slurm-tasks four", "not a whole number"}},
        {sweep + " --slurm-tasks 2", {"--slurm-tasks 2 needs --out DIR --plan-only", "1 to 10000"}},
        {sweep + " --plan-only --slurm-cpus-per-task 4", {"--slurm-cpus-per-task 4 needs --slurm-tasks N", "1 to 10000"}},
        {sweep + " --plan-only --slurm-tasks 2 --slurm-cpus-per-task 0",
         {"--slurm-cpus-per-task 0 is out of range (allowed: 1 to 1024)"}},
        {sweep + " --plan-only --slurm-no-submit", {"--slurm-no-submit needs --slurm-tasks N"}},
        {sweep + " --plan-only --slurm-tasks 5", {"--slurm-tasks 5 is more tasks than the plan has runs", "1 to 4"}},
        {" validate --only fig7-hexagon-rolls --seeds 1 --out " + out.string() + " --slurm-tasks 2 --shard 1/2",
         {"--slurm-tasks 2 and --shard 1/2 are both given"}},
        {" validate --only fig7-hexagon-rolls --seeds 1 --out " + out.string() + " --slurm-tasks 0",
         {"--slurm-tasks 0 is out of range (allowed: 1 to 10000)"}},
        {" validate --only fig7-hexagon-rolls --seeds 1 --out " + out.string() + " --slurm-no-submit",
         {"--slurm-no-submit needs --slurm-tasks N"}},
    };
    for (const Case& c : cases) polyroll::test::expect_refused(kPolyrollExe + c.args, c.words, out);
}
