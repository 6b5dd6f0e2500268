#include "render/batch_order.hpp"

#include <algorithm>

namespace strata {

void orderRunsNearestFirst(std::vector<int>& order, const std::function<bool(int, int)>& sameRun,
                           const std::function<float(int)>& nearest) {
    struct Run {
        std::size_t begin, end;
        float nearest;
    };
    std::vector<Run> runs;
    for (std::size_t i = 0; i < order.size();) {
        Run run{i, i + 1, nearest(order[i])};
        while (run.end < order.size() && sameRun(order[i], order[run.end]))
            run.nearest = std::min(run.nearest, nearest(order[run.end++]));
        runs.push_back(run);
        i = run.end;
    }
    if (runs.size() < 2) return;
    std::stable_sort(runs.begin(), runs.end(), [](const Run& a, const Run& b) { return a.nearest < b.nearest; });
    std::vector<int> sorted;
    sorted.reserve(order.size());
    for (const Run& r : runs) sorted.insert(sorted.end(), order.begin() + std::ptrdiff_t(r.begin), order.begin() + std::ptrdiff_t(r.end));
    order = std::move(sorted);
}

}  // namespace strata
