// The reference-point cycle of one axis, exactly as manual 2.6.4:
//  1) direction from ПБТ В "-" (C9/C61): the cycle starts on «ПЕРЕМЕЩЕНИЕ В +»
//     (or «В -»);
//  2) off the deceleration cam: F СТАРТ БТ (C43) towards it;
//  3) cam pressed (Z1005.3 0->1): brake to F ОТКЛ.БТ (C44); S конечника БТ
//     (C48) limits the travel on the cam (its sign gives the direction) —
//     alarm 40 «Нет съезда с конечника "0"» when the cam is not left in it;
//  4) cam released (1->0): travel S до поиска 0-метки (C37, signed), then
//     search the zero mark, at most S поиска 0-метки (C38; its sign gives the
//     direction, 0 = unlimited in the same direction) — alarm 41 «Нет
//     "0"-метки» when it ends without a mark;
//  5) from the mark travel СМЕЩЕНИЕ БТ (C39); that point gets ЗНАЧЕНИЕ БТ
//     (C45) in the machine system;
//  6) the axis is referenced (the «X»/«Z» flag of the ПБТ screen).
// Distances are in display discretes of the axis, speeds in 10·disc/min.
#pragma once

#include <cstdint>

#include "axis/servo.h"

namespace k528::axis {

class HomingCycle {
public:
    enum class Phase {
        Idle,
        Approach,      // towards the cam at F СТАРТ БТ
        OnCam,         // on the cam at F ОТКЛ.БТ, waiting for its release
        BeforeSearch,  // S до поиска 0-метки
        Search,        // looking for the zero mark
        ToReference,   // СМЕЩЕНИЕ БТ from the mark
        Done,
        Failed,
    };

    // Starts the cycle (the operator's direction key). `camPressed`: the
    // deceleration cam signal now. Returns false if the servo refused to move.
    bool start(Servo& servo, bool camPressed);
    // Cancels the cycle (mode change, reset, stop): the axis decelerates.
    void cancel(Servo& servo);

    // One control period, after servo.tick(). `camPressed`: Z1005.3 / fast
    // input function 6.
    void tick(Servo& servo, bool camPressed);

    Phase phase() const { return phase_; }
    // Approach .. ToReference (one comparison: the engine asks every tick).
    bool running() const {
        return static_cast<unsigned>(phase_) - static_cast<unsigned>(Phase::Approach) <=
               static_cast<unsigned>(Phase::ToReference) - static_cast<unsigned>(Phase::Approach);
    }
    bool done() const { return phase_ == Phase::Done; }
    // 40 or 41 after a failure, else 0.
    int alarm() const { return alarm_; }
    // R246/R247: distance from where the axis left the cam to the zero mark
    // (while searching: to the current position), display discretes.
    std::int64_t distanceDisc() const { return distanceDisc_; }

private:
    void fail(Servo& servo, int alarm);
    void beginSearch(Servo& servo);

    Phase phase_ = Phase::Idle;
    int dir_ = 1;          // direction of the current travel
    bool camWas_ = false;
    double camStart_ = 0;  // where the cam was pressed (internal)
    double leftCam_ = 0;   // where the cam was released
    double searchStart_ = 0;
    double reference_ = 0; // mark + СМЕЩЕНИЕ БТ (internal, machine system before the shift)
    int alarm_ = 0;
    std::int64_t distanceDisc_ = 0;
};

} // namespace k528::axis
