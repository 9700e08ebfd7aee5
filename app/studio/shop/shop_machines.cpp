#include "shop/shop_machines.h"

#include "session/shop_database.h"

namespace k528::studio {

std::vector<ShopMachine> shopMachines(QString* error) {
    std::vector<ShopMachine> out;
    try {
        ShopDatabase::at(ShopDatabase::current())->use([&](db::Database& d) {
            for (const db::MachineInfo& i : d.machines()) {
                const auto line = d.loadMachine(i.name).simulation.find("line");
                if (!line)
                    continue;
                std::string why;
                const auto a = profile::parseLine(*line, why);
                if (!a)
                    continue;
                out.push_back({QString::fromStdString(i.name), profile::formatLine(*a), *a});
            }
        });
    } catch (const std::exception& e) {
        out.clear();
        if (error)
            *error = databaseErrorText(e);
    }
    return out;
}

} // namespace k528::studio
