// One printable line from any bytes: see message_text.h.
#include "sim/message_text.h"

#include <cctype>
#include <cmath>
#include <system_error>

#include <fmt/core.h>

namespace polyroll {
namespace {

// Length of the valid UTF-8 sequence starting at text[i], or 0 if there is none (overlong forms,
// surrogates and code points above U+10FFFF are invalid too).
std::size_t utf8_length(std::string_view text, std::size_t i) {
    const auto b = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned char c = b(i);
    std::size_t n = 0;
    unsigned min = 0;
    unsigned cp = 0;
    if (c >= 0xC2 && c <= 0xDF) { n = 2; min = 0x80; cp = c & 0x1Fu; }
    else if (c >= 0xE0 && c <= 0xEF) { n = 3; min = 0x800; cp = c & 0x0Fu; }
    else if (c >= 0xF0 && c <= 0xF4) { n = 4; min = 0x10000; cp = c & 0x07u; }
    else return 0;
    if (i + n > text.size()) return 0;
    for (std::size_t k = 1; k < n; ++k) {
        if ((b(i + k) & 0xC0u) != 0x80u) return 0;
        cp = (cp << 6u) | (b(i + k) & 0x3Fu);
    }
    if (cp < min || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return 0;
    return n;
}

}  // namespace

std::string printable_line(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c >= 0x20 && c < 0x7F) {
            out += static_cast<char>(c);
            ++i;
        } else if (const std::size_t n = c >= 0x80 ? utf8_length(text, i) : 0; n > 0) {
            out.append(text.substr(i, n));
            i += n;
        } else {
            out += fmt::format("\\x{:02X}", static_cast<unsigned>(c));
            ++i;
        }
    }
    return out;
}

std::string open_failure_reason(int error_number) {
    if (error_number == 0) return "cannot be read";
    std::string reason = std::generic_category().message(error_number);
    // The C library's sentence case ("No such file or directory") reads oddly after a colon.
    if (!reason.empty()) reason[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(reason[0])));
    return "cannot be read: " + reason;
}

std::string json_error_text(std::string_view what) {
    constexpr std::string_view prefix = "[json.exception.";
    if (what.substr(0, prefix.size()) == prefix) {
        const std::size_t end = what.find("] ");
        if (end != std::string_view::npos) what.remove_prefix(end + 2);
    }
    return std::string(what);
}

std::string real_time_text(double simulated_s, double wall_s) {
    if (wall_s <= 0.0) return "too fast to time";
    const double factor = simulated_s / wall_s;
    return factor >= 10.0 ? fmt::format("{:.0f}x real time", factor) : fmt::format("{:.2g}x real time", factor);
}

std::string comma_list(const std::vector<std::string>& items) {
    std::string out;
    for (const std::string& item : items) out += (out.empty() ? "" : ", ") + item;
    return out;
}

std::string fixed_or_dash(double v, int digits) {
    return std::isfinite(v) ? fmt::format("{:.{}f}", v, digits) : "-";
}

std::string counted(long long n, std::string_view noun) {
    return std::to_string(n) + " " + std::string(noun) + (n == 1 ? "" : "s");
}

}  // namespace polyroll
