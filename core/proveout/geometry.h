// What the prove-out of a program knows of the machine (docs/machine-description.md,
// section "proveout"): the spindles and what the M functions do to them, the
// M functions that change the tool, the chuck with its jaws, the turret, and
// on a grinder the ring the wheel grinds (its equipment's "grinding.ring").
//
// Coordinates are those of the machine (machine system, as the panel shows
// them), lengths in mm, radial sizes as radii or diameters as named. The
// geometry of a turret is relative to the machine's reference point: the
// point whose machine coordinates the positioner shows, the tip of a tool
// whose offsets are 0.
#pragma once

#include "plc/description.h"
#include "profile/profile.h"

#include <map>
#include <string>
#include <vector>

namespace k528::proveout {

// A spindle ("spindle", "wheel", "work") and the M functions that start and stop it.
struct SpindleUse {
    std::string name;
    std::vector<int> on, off;
};

// A three-jaw chuck seen in the (z, r) plane (it turns: a body of revolution).
// The jaws stand on the chuck's face towards +Z up to `jawFaceZMm`; they grip
// the part at its diameter (the blank's, else `gripDiameterMm`) and reach
// `jawHeightMm` above it. The body is a cylinder behind the jaws.
struct ChuckGeometry {
    bool present = false;
    double jawFaceZMm = 0;     // machine Z of the jaws' front faces
    double jawLengthMm = 0;    // along Z, from the chuck's face to the jaws' front
    double jawHeightMm = 0;    // radially, above the gripped diameter
    double gripDiameterMm = 0; // the diameter gripped when no blank says otherwise
    double bodyDiameterMm = 0;
    double bodyLengthMm = 0;
};

// The turret (a tool post with its stations and the tools not in use) as a
// box around the reference point: z in [zMinMm, zMaxMm], radius (half of a
// diameter axis' X) in [rMinMm, rMaxMm], relative to the reference point.
struct TurretGeometry {
    bool present = false;
    double zMinMm = 0, zMaxMm = 0, rMinMm = 0, rMaxMm = 0;
};

// The grinder's ring (equipment.grinding.ring): its bore before grinding and
// where along Z (machine) the wheel is in it.
struct RingGeometry {
    bool present = false;
    double blankBoreMm = 0;
    double zMinMm = 0, zMaxMm = 0;
};

struct MachineGeometry {
    std::string machine; // the description's name
    std::vector<SpindleUse> spindles;
    // The spindle that must turn while a feed cuts: the lathe's spindle, the
    // grinder's wheel ("" when the description names none).
    std::string cuttingSpindle;
    std::map<int, int> toolChange; // M function -> turret station
    int firstStation = 0;          // station at power-on (equipment.turret.position), 0 none
    ChuckGeometry chuck;
    TurretGeometry turret;
    RingGeometry ring;

    const SpindleUse* spindle(std::string_view name) const;
};

// Reads the description's "proveout" section and what it uses of "equipment";
// throws plc::DescriptionError (file, path, what is wrong). A description
// without the section has no geometry (the rules that need it stay silent).
MachineGeometry readGeometry(const plc::MachineDescription& d);

// The geometry of the machine a profile runs (its description, as the
// simulated machine finds it: machine::Simulation::descriptionFor).
MachineGeometry geometryOf(const profile::MachineProfile& p);

} // namespace k528::proveout
