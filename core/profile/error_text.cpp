#include "profile/error_text.h"

#include "profile/calculator.h"
#include "profile/cutting.h"
#include "profile/tools.h"
#include "profile/text_format.h"

namespace k528::profile {

std::string fileErrorText(const FileError& e, bool russian) {
    if (!russian)
        return e.what();
    // The shape of what(): "<source>:<line>: <problem>", as a compiler's.
    return e.source() + (e.line() > 0 ? ":" + std::to_string(e.line()) : std::string()) + ": " +
           problemText(e.problem(), true);
}

std::string errorText(const std::exception& e, bool russian) {
    if (const auto* f = dynamic_cast<const FileError*>(&e))
        return fileErrorText(*f, russian);
    if (const auto* c = dynamic_cast<const cutting::CuttingError*>(&e))
        return problemText(c->problem, russian);
    if (const auto* c = dynamic_cast<const calc::CalcError*>(&e))
        return problemText(c->problem, russian);
    if (const auto* t = dynamic_cast<const ToolError*>(&e))
        return problemText(t->problem(), russian);
    return e.what();
}

} // namespace k528::profile
