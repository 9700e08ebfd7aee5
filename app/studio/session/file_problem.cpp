#include "session/file_problem.h"

#include "session/core_texts.h"

namespace k528::studio {

QString fileProblem(const SaveFile& f) {
    return systemText(f.reason());
}

} // namespace k528::studio
