// The studio's simulated controller behind the seam, for the tests of the
// views that reach a controller only through it: a SimulationSession of a
// profile, its SimulatedController and the ViewedController the views are
// given. A test linking k528studio_ui includes it.
#pragma once

#include "controller/simulated_controller.h"
#include "profile/builtin.h"
#include "rig/controller_rig.h"
#include "session/simulation_session.h"

#include <string>

namespace k528::testrig {

struct SimulatedSeam {
    explicit SimulatedSeam(const profile::MachineProfile& p) : session(p), controller(session), seam(controller) {}
    studio::SimulationSession session;
    studio::SimulatedController controller;
    studio::ViewedController seam;
};

// The training lathe under another name (each test its own machine in the
// database), edited by `tweak`.
inline profile::MachineProfile latheNamed(const std::string& name, const ProfileTweak& tweak = {}) {
    profile::MachineProfile p = tweakedProfile("training-lathe", tweak);
    p.name = name;
    return p;
}

} // namespace k528::testrig
