// Files written whole or not at all: each is written under a temporary name in the same folder and
// renamed into place, so a crash leaves the old file or the new one, never half of one.
#pragma once

#include <filesystem>
#include <optional>
#include <string_view>

namespace polyroll {

// Whether the data must reach the disk before the rename. Results are synced; frames, which are
// cheap to make again and come by the hundred, need not be (a crash then loses recent frames, but
// never leaves half of one).
enum class Durability { synced, unsynced };

// Throws std::runtime_error naming the path on any failure (the temporary is removed).
void write_file_atomic(const std::filesystem::path& path, std::string_view content,
                       Durability durability = Durability::synced);

// Makes `dir` ready for a run's files before any work is done, so a bad folder fails at once.
// Refuses a non-empty folder unless `force`; checks that files can be created in it; removes the
// temporaries of killed writers (write_file_atomic's, whose process is gone). Returns the
// topmost folder it created, if any, for the caller to remove if the run fails. Throws InputError;
// for a non-empty folder its message ends with `remedy`, which a command without --force changes.
inline constexpr std::string_view kForceRemedy = "use --force to overwrite its files, or choose a new folder";
std::optional<std::filesystem::path> prepare_output_dir(const std::filesystem::path& dir, bool force,
                                                        std::string_view remedy = kForceRemedy);

}  // namespace polyroll
