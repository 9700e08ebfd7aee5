// db::Edit: single items changed, as `k528 db set` gives them.
#include "catalog/cparams.h"
#include "db/database.h"
#include "db/revisions.h"

namespace k528::db {

namespace cat = k528::catalog;
using profile::MachineProfile;

std::string Edit::describe() const {
    std::string s;
    const auto add = [&](const std::string& k) { s += (s.empty() ? "" : " ") + k; };
    if (title)
        add("title");
    for (const auto& [n, v] : c)
        add(cat::cParam(n).key());
    for (const auto& [n, v] : r)
        add("R" + std::to_string(n));
    for (const auto& [n, v] : messages)
        add("#" + std::to_string(n));
    for (const auto& [gk, v] : plc)
        add(revision::plcKey(gk.first, gk.second));
    for (const auto& [k, v] : simulation)
        add(k);
    return s;
}

void Edit::applyTo(MachineProfile& p) const {
    if (title)
        p.title = *title;
    for (const auto& [n, v] : c)
        p.setC(n, v);
    for (const auto& [n, v] : r) {
        if (v)
            p.r[n] = *v;
        else
            p.r.erase(n);
    }
    for (const auto& [n, v] : messages) {
        if (v)
            p.messages[n] = *v;
        else
            p.messages.erase(n);
    }
    for (const auto& [gk, v] : plc) {
        auto& m = p.plcTexts(gk.first);
        if (v)
            m[gk.second] = *v;
        else
            m.erase(gk.second);
    }
    for (const auto& [k, v] : simulation) {
        if (v)
            p.simulation.set(k, *v);
        else
            p.simulation.erase(k);
    }
}

} // namespace k528::db
