#include "profile/error_text.h"
#include "machine_profile.h"

#include "db/error.h"
#include "db/location.h"
#include "profile/builtin.h"

#include <cstdio>
#include <exception>
#include <string>

namespace k528::cli {

std::optional<profile::MachineProfile> machineProfile(const Args& args) {
    const std::string name = args.value("--profile").value_or(std::string(profile::kDefaultProfile));
    try {
        return db::loadProfile(name, args.value("--db").value_or(std::string()));
    } catch (const db::Error& e) {
        // In the command's --lang (Russian unless "en", as every command's default).
        std::fprintf(stderr, "k528: %s\n", e.text(args.value("--lang") != "en" ? db::Lang::Ru : db::Lang::En).c_str());
        return std::nullopt;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "k528: %s\n", profile::errorText(e, args.value("--lang") != "en").c_str());
        return std::nullopt;
    }
}

} // namespace k528::cli
