// Messages for people: bad input can carry any bytes (a file name, a flag value, a scene file's
// strings), and the CLI promises one readable line. printable_line() makes any text such a line.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace polyroll {

// Valid UTF-8 (printable) passes through; control bytes, newlines and bytes that are not valid
// UTF-8 become \xNN escapes, so the result is one line of valid UTF-8 whatever the input.
std::string printable_line(std::string_view text);

// Why opening a file failed, from the errno the failed open left: "no such file or directory",
// "permission denied"; "cannot be read" when the system gave no reason (errno 0).
std::string open_failure_reason(int error_number);

// nlohmann::json's message without its "[json.exception.parse_error.101] " prefix, which means nothing
// to a user; the rest ("parse error at line 3, column 12: ...") names the place and stays.
std::string json_error_text(std::string_view what);

// How fast a run went against the wall clock: "120x real time", "5.3x real time", "0.25x real time".
// Whole numbers hide nothing above 10x, but a run at 0.4x printed as "0x": below 10x, two
// significant digits. "too fast to time" when the clock saw no time pass.
std::string real_time_text(double simulated_s, double wall_s);

// Items as a message lists them: "bb, rice, peas" ("" for none).
std::string comma_list(const std::vector<std::string>& items);

// A number with `digits` decimals, or "-" for NaN or infinity (a table cell with nothing measured).
std::string fixed_or_dash(double v, int digits);

// A count with its noun: "1 run", "24 runs" (the plural adds an s: the nouns counted are regular).
std::string counted(long long n, std::string_view noun);

}  // namespace polyroll
