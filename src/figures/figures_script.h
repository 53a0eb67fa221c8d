// Finding and running the figure script (polyroll_figures.py, matplotlib) from the C++ commands:
// the script beside an installed binary, or in the source tree the binary was built from.
#pragma once

#include <string>
#include <vector>

namespace polyroll::figures {

// The script's path: $POLYROLL_FIGURES_DIR, then <exe>/../share/polyroll/figures, then the source
// tree. Throws std::runtime_error listing the places tried.
std::string figures_script();

// A Python 3 that can import matplotlib and numpy: $POLYROLL_PYTHON, else /usr/bin/python3 (where
// Debian's python3-matplotlib lives), else python3 on the PATH. Throws std::runtime_error saying what to
// install when none can.
std::string figures_python();

// Runs the script with `args` (no shell); returns its exit code.
int run_figures_script(const std::vector<std::string>& args);

}  // namespace polyroll::figures
