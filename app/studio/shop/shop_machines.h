// The machines of the window's database that know where their controller
// is (their `line` setting, as `k528 shop status` reads it: tcp://HOST:PORT/UNIT
// or serial:DEVICE?…), for the Controller dock's Connect and the Shop view.
#pragma once

#include "profile/line.h"

#include <QString>
#include <string>
#include <vector>

namespace k528::studio {

struct ShopMachine {
    QString name;
    std::string line; // the canonical text (profile::formatLine)
    profile::LineAddress address;
};

// In the database's order; `error` says why the database could not be read
// (then the list is empty). A machine whose line is not a line is left out.
std::vector<ShopMachine> shopMachines(QString* error = nullptr);

} // namespace k528::studio
