#include "proveout/geometry.h"

#include "machine/simulation.h"
#include "plc/json_reader.h"
#include "util/json.h"

#include <algorithm>

namespace k528::proveout {

const SpindleUse* MachineGeometry::spindle(std::string_view name) const {
    for (const SpindleUse& s : spindles)
        if (s.name == name)
            return &s;
    return nullptr;
}

namespace {

// The names of the spindles the equipment has.
std::vector<std::string> equipmentSpindles(const plc::MachineDescription& d) {
    std::vector<std::string> names;
    if (!d.equipment || !d.equipment->is_object() || !d.equipment->contains("spindles"))
        return names;
    for (const Json& s : d.equipment->at("spindles"))
        if (s.is_object() && s.contains("name") && s.at("name").is_string())
            names.push_back(s.at("name").get<std::string>());
    return names;
}

std::vector<int> mList(const plc::JsonNode& n, std::string_view key,
                       const plc::MachineDescription& d) {
    std::vector<int> out;
    if (!n.has(key))
        return out;
    const plc::JsonNode list = n.child(key);
    for (const plc::JsonNode& e : list.elements()) {
        const int m = static_cast<int>(e.asInteger(0, 99));
        if (!d.mFunction(m))
            e.fail(profile::problem("proveout.not-m", {std::to_string(m)}));
        out.push_back(m);
    }
    return out;
}

} // namespace

MachineGeometry readGeometry(const plc::MachineDescription& d) {
    MachineGeometry g;
    g.machine = d.name;
    const Json& eq = d.equipment ? *d.equipment : Json::object();
    if (eq.is_object() && eq.contains("turret") && eq.at("turret").is_object()) {
        const Json& t = eq.at("turret");
        g.firstStation = t.contains("position") && t.at("position").is_number_integer()
                             ? t.at("position").get<int>()
                             : 1;
    }
    if (eq.is_object() && eq.contains("grinding") && eq.at("grinding").is_object()) {
        const plc::JsonNode ring(eq.at("grinding").at("ring"), d.source, "equipment.grinding.ring");
        g.ring.present = true;
        g.ring.blankBoreMm = ring.number("blank_bore_mm", 0.1, 10000);
        g.ring.zMinMm = ring.number("z_min_mm", -100000, 100000);
        g.ring.zMaxMm = ring.number("z_max_mm", -100000, 100000);
    }
    if (!d.document || !d.document->contains("proveout"))
        return g;
    const plc::JsonNode p(d.document->at("proveout"), d.source, "proveout");
    p.expectObject({"spindles", "cutting_spindle", "tool_change", "chuck", "turret"});
    const std::vector<std::string> known = equipmentSpindles(d);
    for (const plc::JsonNode& n : p.optionalArray("spindles")) {
        n.expectObject({"name", "on", "off"});
        SpindleUse s;
        s.name = n.string("name");
        if (std::find(known.begin(), known.end(), s.name) == known.end())
            n.failAt("name", profile::problem("proveout.not-spindle", {s.name}));
        if (g.spindle(s.name))
            n.failAt("name", profile::problem("equipment.spindle-twice", {s.name}));
        s.on = mList(n, "on", d);
        s.off = mList(n, "off", d);
        for (int m : s.on)
            if (std::find(s.off.begin(), s.off.end(), m) != s.off.end())
                n.failAt("off", profile::problem("proveout.on-off", {std::to_string(m)}));
        g.spindles.push_back(std::move(s));
    }
    if (p.has("cutting_spindle")) {
        g.cuttingSpindle = p.string("cutting_spindle");
        if (!g.spindle(g.cuttingSpindle))
            p.failAt("cutting_spindle", profile::problem("proveout.cutting-spindle", {g.cuttingSpindle}));
    }
    for (const plc::JsonNode& n : p.optionalArray("tool_change")) {
        n.expectObject({"m", "station"});
        const int m = static_cast<int>(n.integer("m", 0, 99));
        if (!d.mFunction(m))
            n.failAt("m", profile::problem("proveout.not-m", {std::to_string(m)}));
        if (g.toolChange.count(m))
            n.failAt("m", profile::problem("proveout.tool-twice", {std::to_string(m)}));
        const int positions =
            eq.is_object() && eq.contains("turret") && eq.at("turret").contains("positions")
                ? eq.at("turret").at("positions").get<int>()
                : 0;
        if (positions == 0)
            n.fail(profile::problem("proveout.no-turret"));
        g.toolChange[m] = static_cast<int>(n.integer("station", 1, positions));
    }
    if (p.has("chuck")) {
        const plc::JsonNode c = p.child("chuck");
        c.expectObject({"jaw_face_z_mm", "jaw_length_mm", "jaw_height_mm", "grip_diameter_mm",
                        "body_diameter_mm", "body_length_mm"});
        ChuckGeometry& k = g.chuck;
        k.present = true;
        k.jawFaceZMm = c.number("jaw_face_z_mm", -100000, 100000);
        k.jawLengthMm = c.number("jaw_length_mm", 0, 1000);
        k.jawHeightMm = c.number("jaw_height_mm", 0, 1000);
        k.gripDiameterMm = c.number("grip_diameter_mm", 0, 10000);
        k.bodyDiameterMm = c.number("body_diameter_mm", 0, 10000);
        k.bodyLengthMm = c.number("body_length_mm", 0, 10000);
    }
    if (p.has("turret")) {
        const plc::JsonNode t = p.child("turret");
        t.expectObject({"z_min_mm", "z_max_mm", "r_min_mm", "r_max_mm"});
        TurretGeometry& k = g.turret;
        k.present = true;
        k.zMinMm = t.number("z_min_mm", -10000, 10000);
        k.zMaxMm = t.number("z_max_mm", -10000, 10000);
        k.rMinMm = t.number("r_min_mm", -10000, 10000);
        k.rMaxMm = t.number("r_max_mm", -10000, 10000);
        if (k.zMinMm >= k.zMaxMm || k.rMinMm >= k.rMaxMm)
            t.fail(profile::problem("proveout.turret-box"));
    }
    return g;
}

MachineGeometry geometryOf(const profile::MachineProfile& p) {
    return readGeometry(machine::Simulation::descriptionFor(p));
}

} // namespace k528::proveout
