// Wrapping the panel's prose at spaces only: see text_wrap.h.
#include "app/text_wrap.h"

namespace polyroll::app {

std::vector<std::string> wrap_at_spaces(std::string_view text, float width,
                                        const std::function<float(std::string_view)>& measure) {
    std::vector<std::string> lines;
    size_t start = 0;
    while (start <= text.size()) {
        const size_t newline = text.find('\n', start);
        const std::string_view paragraph =
            text.substr(start, newline == std::string_view::npos ? std::string_view::npos : newline - start);
        // Greedy: each line takes words while the line still fits.
        std::string line;
        size_t pos = 0;
        while (pos <= paragraph.size()) {
            const size_t space = paragraph.find(' ', pos);
            const std::string_view word =
                paragraph.substr(pos, space == std::string_view::npos ? std::string_view::npos : space - pos);
            if (line.empty()) {
                line = word;
            } else if (measure(line + " " + std::string(word)) <= width) {
                line += " ";
                line += word;
            } else {
                lines.push_back(line);
                line = word;
            }
            if (space == std::string_view::npos) break;
            pos = space + 1;
        }
        lines.push_back(line);
        if (newline == std::string_view::npos) break;
        start = newline + 1;
    }
    return lines;
}

}  // namespace polyroll::app
