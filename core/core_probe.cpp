// Links every core module; prints the version and the embedded resources.
// Used by the test architecture.core_has_no_qt (ldd must show no Qt library).
#include <cstdio>

#include "resources/embedded.h"
#include "util/version.h"

int main() {
    std::printf("k528 core %s\n", k528::version_string);
    for (const auto& r : k528::resources::all())
        std::printf("%.*s %zu\n", static_cast<int>(r.path.size()), r.path.data(), r.data.size());
    return 0;
}
