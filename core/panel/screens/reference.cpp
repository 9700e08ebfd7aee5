#include "panel/screens/reference.h"

namespace k528::panel {

void ReferenceScreen::render(Canvas& c, const Context& ctx) const {
    const engine::Positioner& e = ctx.engine();
    c.put(0, 1, engine::modeTagRu(engine::Mode::Reference));
    for (int i = 0; i < engine::kAxisCount; ++i) {
        const engine::AxisView v = e.axisView(engine::axisAt(i));
        if (!v.present)
            continue;
        if (v.referenced)
            c.put(0, i == 0 ? 5 : 7, i == 0 ? "X" : "Z");
        std::string s = v.moving ? "*" : " ";
        s += i == 0 ? "X" : "Z";
        s += padLeft(formatCoordinate(v.currentDisc, v.scale), 9);
        s += "#" + formatCoordinate(v.homeDistanceDisc, v.scale);
        c.put(2 + i, 1, s);
    }
    renderOverride(c, ctx);
}

} // namespace k528::panel
