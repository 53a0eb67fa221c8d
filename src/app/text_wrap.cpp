// Wrapping the panel's prose at spaces only: see text_wrap.h.
#include "app/text_wrap.h"

namespace polyroll::app {

std::vector<std::string> wrap_at_spaces(std::string_view text, float width,
                                        const std::function<float(std::string_view)>& measure) {
    std::vector<std::string> lines;
    size_t start = 0;
    while (true) {
        const size_t newline = text.find('\n', start);
        const std::string_view paragraph =
            text.substr(start, newline == std::string_view::npos ? std::string_view::npos : newline - start);
        // Greedy: each line is a stretch of the paragraph that takes words while it still fits, so
        // it is measured in place, without building it.
        size_t line_start = 0, line_end = 0;  // the line so far: [line_start, line_end)
        bool line_empty = true;
        size_t pos = 0;
        while (true) {
            const size_t space = paragraph.find(' ', pos);
            const size_t word_end = space == std::string_view::npos ? paragraph.size() : space;
            if (line_empty) {
                line_start = pos;
                line_empty = false;
            } else if (measure(paragraph.substr(line_start, word_end - line_start)) > width) {
                lines.emplace_back(paragraph.substr(line_start, line_end - line_start));
                line_start = pos;
            }
            line_end = word_end;
            if (space == std::string_view::npos) break;
            pos = space + 1;
        }
        lines.emplace_back(paragraph.substr(line_start, line_end - line_start));
        if (newline == std::string_view::npos) break;
        start = newline + 1;
    }
    return lines;
}

}  // namespace polyroll::app
