#include "proveout/rules.h"

#include <array>

namespace k528::proveout {

namespace {
constexpr std::array<Rule, 7> kRules{Rule::RapidIntoMaterial,  Rule::ToolIntoChuck,
                                     Rule::TurretIntoChuck,    Rule::FeedSpindleStopped,
                                     Rule::FeedWheelStopped,   Rule::CutTooDeep,
                                     Rule::ManualIntoMaterial};
} // namespace

std::string_view ruleId(Rule r) {
    switch (r) {
    case Rule::RapidIntoMaterial:
        return "rapid-into-material";
    case Rule::ToolIntoChuck:
        return "tool-into-chuck";
    case Rule::TurretIntoChuck:
        return "turret-into-chuck";
    case Rule::FeedSpindleStopped:
        return "feed-spindle-stopped";
    case Rule::FeedWheelStopped:
        return "feed-wheel-stopped";
    case Rule::CutTooDeep:
        return "cut-too-deep";
    case Rule::ManualIntoMaterial:
        return "manual-into-material";
    }
    return "";
}

std::span<const Rule> allRules() {
    return kRules;
}

std::optional<Rule> materialRule(Motion m, bool cuttingSpindleTurning, bool grinder) {
    switch (m) {
    case Motion::Rapid:
        return Rule::RapidIntoMaterial;
    case Motion::Manual:
        return Rule::ManualIntoMaterial;
    case Motion::Feed:
        if (cuttingSpindleTurning)
            return std::nullopt;
        return grinder ? Rule::FeedWheelStopped : Rule::FeedSpindleStopped;
    }
    return std::nullopt;
}

ChuckBoxes chuckBoxes(const ChuckGeometry& c, double gripDiameterMm) {
    const double grip = gripDiameterMm > 0 ? gripDiameterMm : c.gripDiameterMm;
    ChuckBoxes b;
    b.jaws = {c.jawFaceZMm - c.jawLengthMm, c.jawFaceZMm, grip / 2, grip / 2 + c.jawHeightMm};
    b.body = {c.jawFaceZMm - c.jawLengthMm - c.bodyLengthMm, c.jawFaceZMm - c.jawLengthMm, 0,
              c.bodyDiameterMm / 2};
    return b;
}

ChuckHit chuckContact(const ChuckBoxes& chuck, const Box& box, PointZR a, PointZR b) {
    const Box bounds = box.sweptBounds(a, b);
    for (const auto& [part, kind] :
         {std::pair{chuck.jaws, ChuckContact::Jaws}, std::pair{chuck.body, ChuckContact::Body}}) {
        for (const Box& obstacle : {part, part.mirrored()}) {
            if (!bounds.overlaps(obstacle, kContactEpsMm) ||
                !Sweep(box, a, b).overlaps(obstacle, kContactEpsMm) ||
                box.moved(a).overlaps(obstacle, kContactEpsMm))
                continue;
            return {kind, obstacle};
        }
    }
    return {};
}

} // namespace k528::proveout
