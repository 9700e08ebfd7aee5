// The K923's own state that table М.1 of appendix М reports: its links to the
// PLC and to the positioner (БП), its self-test, and the PLC's debug stop.
// The owner of the panel (the simulated machine's session, a link plugin)
// sets it; the panel shows the manual's message and acts as the hardware:
//   ramOk / residentOk false   «НЕИСПРАВНО ОЗУ» / «НАРУШЕН РЕЗИДЕНТ» on line 1,
//                              nothing else; no key works, no LED lights
//   positionerLink false       «НЕТ СВЯЗИ С БП» on line 1, the screens are gone;
//                              K keys and LEDs still go through the PLC
//   plcLink false              «НЕТ СВЯЗИ С ПЛК» on line 2; K keys are lost,
//                              the LEDs dark (Z1300, Z1906/Z1907 are the PLC's)
//   plcStopped                 «Режим ПЛК СТОП !» on line 2
#pragma once

namespace k528::panel {

struct Health {
    bool ramOk = true;
    bool residentOk = true;
    bool positionerLink = true;
    bool plcLink = true;
    bool plcStopped = false;
    friend bool operator==(const Health&, const Health&) = default;
};

} // namespace k528::panel
