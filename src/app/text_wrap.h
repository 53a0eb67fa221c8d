// Wrapping the panel's prose at spaces only. Dear ImGui 1.86's own wrapping may also break a line
// after '.', ',' and the like, which split numbers across lines ("(7.<newline>00 s)", "rigid, hops from
// 0.<newline>65 s"). GL-free: the window passes ImGui's text measure; the tests pass their own.
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace polyroll::app {

// The lines of `text` no wider than `width` by `measure`, broken only at spaces and at '\n'; the
// spaces at a break are dropped. A word wider than `width` has a line to itself, unbroken.
std::vector<std::string> wrap_at_spaces(std::string_view text, float width,
                                        const std::function<float(std::string_view)>& measure);

}  // namespace polyroll::app
