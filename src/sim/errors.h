// The one error type for bad input (scene files, flags, presets, output folders). Its message is a
// single line that names the bad value and what is allowed; the CLI prints it and exits with 2.
#pragma once

#include <stdexcept>
#include <string>

namespace polyroll {

class InputError : public std::runtime_error {
public:
    explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace polyroll
