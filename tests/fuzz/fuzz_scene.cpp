// libFuzzer target for the scene-file parser: any bytes, as a scene file, must resolve to a valid
// scene or be refused with an InputError; any other exception, a crash, a hang or a sanitizer
// report is a bug. A scene that resolves must also survive its own written form (scene_to_json).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "sim/errors.h"
#include "sim/message_text.h"
#include "sim/scene/scene_json.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace polyroll;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        const SceneLayer layer = parse_scene_text(text, "fuzz.json");
        const Scene scene = resolve_scene({layer});
        const SceneLayer again{scene_to_json(scene), "resolved scene", {}};
        (void)resolve_scene({again});  // a resolved scene that does not resolve again is a bug
    } catch (const InputError& e) {
        // The message is printed as one line: it must be non-empty whatever the bytes.
        if (printable_line(e.what()).empty()) std::abort();
    }
    return 0;
}
