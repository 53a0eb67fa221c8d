// Finding a script polyroll runs (the figures' matplotlib script, the 3D reference's Yade script):
// the folder an environment variable names, then beside an installed binary
// (<exe>/../share/polyroll/<share_dir>/), then the source tree the binary was built from.
#pragma once

#include <string>

namespace polyroll::process {

struct ScriptPlaces {
    const char* name = "";        // the file, e.g. "polyroll_figures.py"
    const char* what = "";        // for the message, e.g. "the figure script"
    const char* env_dir = "";     // e.g. "POLYROLL_FIGURES_DIR"
    const char* share_dir = "";   // e.g. "figures"
    const char* source_dir = nullptr;  // the source tree's folder, if built with one
};

// The first place holding the script; throws std::runtime_error listing the places tried.
std::string installed_script(const ScriptPlaces& p);

}  // namespace polyroll::process
