# The headers precompiled once per build (POLYROLL_PCH in CMakeLists.txt, and the web build in
# web/CMakeLists.txt): the heavy ones nearly every source file includes. The sources include what
# they use without them.
set(POLYROLL_PCH_HEADERS
  <nlohmann/json.hpp> <fmt/format.h>
  <algorithm> <array> <chrono> <cmath> <cstdint> <cstdio> <filesystem> <fstream> <functional> <map>
  <memory> <optional> <set> <sstream> <stdexcept> <string> <string_view> <utility> <vector>)
