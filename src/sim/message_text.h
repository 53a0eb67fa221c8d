// Messages for people: bad input can carry any bytes (a file name, a flag value, a scene file's
// strings), and the CLI promises one readable line. printable_line() makes any text such a line.
#pragma once

#include <string>
#include <string_view>

namespace polyroll {

// Valid UTF-8 (printable) passes through; control bytes, newlines and bytes that are not valid
// UTF-8 become \xNN escapes, so the result is one line of valid UTF-8 whatever the input.
std::string printable_line(std::string_view text);

}  // namespace polyroll
