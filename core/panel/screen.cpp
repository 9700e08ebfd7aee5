#include "panel/screen.h"

#include "catalog/messages.h"

#include <algorithm>

namespace k528::panel {

void Context::inputError() {
    message_ = std::string(catalog::panelMessage(catalog::PanelMessageId::InputError).textRu);
}

void renderOverride(Canvas& c, const Context& ctx) {
    c.putRight(0, 19, std::to_string(ctx.engine().programView().overridePercent) + "%");
}

int moveMarker(int marker, int step, int count) {
    if (count <= 0)
        return 0;
    return std::clamp(marker + step, 0, count - 1);
}

int windowTop(int top, int marker, int rows, int count) {
    if (count <= rows)
        return 0;
    if (marker < top)
        top = marker;
    if (marker >= top + rows)
        top = marker - rows + 1;
    return std::clamp(top, 0, count - rows);
}

} // namespace k528::panel
