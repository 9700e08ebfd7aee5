#include "shop/state_time.h"

#include <ctime>

namespace k528::shop {

std::string localTimeText(std::int64_t unixMs, const char* format) {
    const std::time_t t = static_cast<std::time_t>(unixMs / 1000);
    std::tm tm{};
    localtime_r(&t, &tm);
    char buf[64];
    const std::size_t n = std::strftime(buf, sizeof buf, format, &tm);
    return std::string(buf, n);
}

std::string localDay(std::int64_t unixMs) { return localTimeText(unixMs, "%Y-%m-%d"); }

void StateTally::add(const std::string& machine, const std::string& day, Activity a, std::int64_t ms) {
    if (ms <= 0)
        return;
    pending_[{machine, day}][static_cast<std::size_t>(a)] += ms;
}

bool StateTally::due(std::int64_t nowMs) const {
    if (lastMs_ < 0)
        lastMs_ = nowMs;
    if (pending_.empty())
        return false;
    return changed_ || nowMs - lastMs_ >= every_;
}

std::vector<StateTally::Row> StateTally::take(std::int64_t nowMs) {
    std::vector<Row> out;
    for (const auto& [key, ms] : pending_)
        for (std::size_t i = 0; i < ms.size(); ++i)
            if (ms[i] > 0)
                out.push_back({key.first, key.second, activityName(static_cast<Activity>(i)), ms[i]});
    pending_.clear();
    changed_ = false;
    lastMs_ = nowMs;
    return out;
}

void StateTally::putBack(const std::vector<Row>& rows) {
    for (const Row& r : rows)
        for (std::size_t i = 0; i < 4; ++i)
            if (r.state == activityName(static_cast<Activity>(i)))
                pending_[{r.machine, r.day}][i] += r.ms;
}

} // namespace k528::shop
