// Without a display the sandbox still shows the default scene: it says so in one line and hands
// over to the sibling polyroll executable's headless render, whose own output says where the
// frames went.
#pragma once

#include <string>

namespace polyroll::app {

// The polyroll executable beside this one (the folder of /proc/self/exe).
std::string sibling_polyroll();

// Prints the line, then replaces this process with `polyroll render --out runs/default --force`.
// Returns only if that could not start (the exit code to use).
int run_headless_instead(const std::string& why);

}  // namespace polyroll::app
