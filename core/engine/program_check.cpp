#include "engine/program_check.h"

#include "catalog/cparams.h"
#include "engine/load_programs.h"

namespace k528::engine {

namespace {

// C-parameters of one axis are C(n) for X and C(n + 52) for Z (app. Е):
// limits C46/C47 are display discretes of the machine system, F УСК.АВТ.
// C42 is 10 discretes/min; the coordinate components come from the
// profile's R presets (app. Л: X even, Z odd).
program::AxisLimits axisLimits(const profile::MachineProfile& p, catalog::Axis axis) {
    using program::Decimal;
    program::AxisLimits a;
    const units::AxisScale scale = profile::axisScale(p, axis);
    const int decimals = scale.decimals();
    a.present = profile::axisPresent(p, axis);
    a.diameter = scale.diameter;
    a.decimals = decimals;
    a.softLimits = profile::axisValue(p, axis, 10) == 1;
    a.minMm = Decimal::fromScaled(profile::axisValue(p, axis, 46), decimals);
    a.maxMm = Decimal::fromScaled(profile::axisValue(p, axis, 47), decimals);
    a.maxFeedMmPerMin = Decimal::fromScaled(profile::axisValue(p, axis, 42) * 10, decimals);
    const int z = axis == catalog::Axis::Z ? 1 : 0;
    const auto preset = [&](int r) {
        const auto it = p.r.find(r + z);
        return Decimal::fromScaled(it == p.r.end() ? 0 : it->second, decimals);
    };
    a.zeroOffsetMm = preset(228);
    a.dressingMm = preset(224);
    a.correctionMm = preset(226);
    a.handwheelMm = preset(230);
    return a;
}

} // namespace

program::ValidateOptions validateOptionsFor(const profile::MachineProfile& p) {
    program::ValidateOptions o;
    program::MachineLimits m;
    m.x = axisLimits(p, catalog::Axis::X);
    m.z = axisLimits(p, catalog::Axis::Z);
    o.machine = m;
    o.nestingLimit =
        static_cast<int>(p.simulation.getInt("nesting_limit", program::kDefaultNestingLimit));
    return o;
}

FileCheck checkFileForMachine(std::string_view text, const program::ParseOptions& parseOptions,
                              const profile::MachineProfile& machine,
                              const program::ProgramStore& machineStore) {
    FileCheck r;
    r.parsed = program::parse(text, parseOptions);
    for (const program::Program& p : r.parsed.store.programs())
        r.programs.insert(p.number);
    if (r.parsed.hasErrors()) {
        r.diagnostics = r.parsed.diagnostics;
        return r;
    }
    program::ProgramStore merged = machineStore;
    mergePrograms(merged, r.parsed.store);
    for (program::Diagnostic& d : program::validate(merged, validateOptionsFor(machine)))
        if (r.programs.count(d.program) || (d.program == 0 && d.line > 0))
            r.diagnostics.push_back(std::move(d));
    return r;
}

} // namespace k528::engine
