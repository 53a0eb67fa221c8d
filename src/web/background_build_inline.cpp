// Lane builds on the page, which has no threads: built at once, on the main loop, the future
// ready when it is returned (the page shows its loading state meanwhile). See background_build.h.
#include "app/background_build.h"

#include <exception>

namespace polyroll::app {

std::future<std::unique_ptr<ModelRun>> build_in_background(LaneBuild build) {
    std::promise<std::unique_ptr<ModelRun>> done;
    try {
        done.set_value(build());
    } catch (...) {
        done.set_exception(std::current_exception());
    }
    return done.get_future();
}

}  // namespace polyroll::app
